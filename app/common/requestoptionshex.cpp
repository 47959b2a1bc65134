// RequestOptions for requests given as bytes (--hex, with --complete): the rest of the class is
// requestoptions.cpp.
#include "common/requestoptions.h"

#include "common/targetoptions.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"
#include "protocol/registerformat.h"

#include <QtCore/QCommandLineParser>

namespace mbscope::app {

namespace {

QString hexName(const QByteArray &bytes)
{
    HexText::FormatOptions options;
    QString text = HexText::format(bytes.left(16), options);
    if (bytes.size() > 16)
        text += QStringLiteral(" ... (%1 bytes)").arg(bytes.size());
    return text;
}

} // namespace

bool RequestOptions::readHex(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                             QString &error) const
{
    const LinkUrl &url = target.url;
    const bool complete = parser.isSet(m_complete);
    int unit = 1;
    if (complete) {
        if (url.delimited.enabled) {
            error = QStringLiteral("--complete adds a Modbus header or checksum, but %1 uses delimited framing: "
                                   "give the whole frame in --hex")
                        .arg(url.toString());
            return false;
        }
        if (!readUnit(parser, unit, error))
            return false;
    } else if (parser.isSet(m_unit)) {
        error = QStringLiteral("--unit applies to built requests and to --complete: the unit of --hex bytes sent as "
                               "they are is in the bytes");
        return false;
    }
    // A poll prints the values of the answers to --hex reads too (--print values), so --format
    // counts for them.
    if (m_groups & Read) {
        out.formats.clear();
        for (const QString &name : parser.value(m_format).split(QLatin1Char(','))) {
            const RegisterFormatResult f = RegisterFormat::parse(name);
            if (!f.ok) {
                error = QStringLiteral("--format: ") + f.error;
                return false;
            }
            out.formats.append(f.format);
        }
    }
    const QStringList texts = parser.values(m_hex);
    if (!m_repeatHex && texts.size() > 1) {
        error = QStringLiteral("--hex is given %1 times: give the bytes once").arg(texts.size());
        return false;
    }
    quint16 transactionId = 1;
    for (qsizetype i = 0; i < texts.size(); ++i) {
        const bool asciiCharacters = !complete && !url.delimited.enabled && url.framing() == Framing::Ascii;
        const FrameTextResult frame = parseFrameText(texts.at(i), asciiCharacters);
        const QString which = texts.size() > 1 ? QStringLiteral("--hex #%1").arg(i + 1) : QStringLiteral("--hex");
        if (!frame.ok) {
            error = which + QStringLiteral(": ") + frame.error;
            return false;
        }
        QByteArray bytes = frame.bytes;
        if (complete) {
            AduOptions options;
            options.framing = url.framing();
            options.unitId = quint8(unit);
            options.transactionId = transactionId++;
            bytes = AduBuilder::complete(bytes, options);
        }
        PlannedRequest r;
        r.item = RequestItem::forLink(bytes, url, hexName(bytes));
        r.description = complete ? QStringLiteral("PDU %1 completed for %2").arg(hexName(frame.bytes), framingName(url.framing()))
                                 : QStringLiteral("%1 bytes as given").arg(bytes.size());
        out.requests.append(r);
    }
    return true;
}

FrameTextResult parseFrameText(const QString &text, bool asciiCharacters)
{
    FrameTextResult result;
    if (asciiCharacters && text.trimmed().startsWith(QLatin1Char(':'))) {
        QByteArray frame = text.trimmed().toLatin1();
        frame.replace("\\r\\n", "\r\n");
        if (!frame.endsWith("\r\n"))
            frame += "\r\n";
        result.bytes = frame;
        result.ok = true;
        return result;
    }
    const HexTextResult parsed = HexText::parse(text);
    if (!parsed.ok) {
        result.error = parsed.error.message;
        const QStringList lines = text.split(QLatin1Char('\n'));
        if (parsed.error.line >= 1 && parsed.error.line <= lines.size()) {
            result.error += QStringLiteral("\n  ") + lines.at(parsed.error.line - 1) + QStringLiteral("\n  ")
                            + QString(qMax(0, parsed.error.column - 1), QLatin1Char(' ')) + QLatin1Char('^');
        }
        return result;
    }
    result.bytes = parsed.bytes;
    result.ok = true;
    return result;
}

} // namespace mbscope::app
