#include "capture/decodecommand.h"

#include "common/cli.h"

#include "protocol/dissectionformat.h"
#include "protocol/dissector.h"
#include "protocol/hextext.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// ASCII frames are typed as their characters (":070300C800042A"); CR LF is added when missing,
// since a shell argument rarely carries it.
QByteArray asciiFrameFromText(const QString &text)
{
    QByteArray frame = text.trimmed().toLatin1();
    frame.replace("\\r\\n", "\r\n");
    if (!frame.endsWith("\r\n"))
        frame += "\r\n";
    return frame;
}

// A serial analyser shows an ASCII frame as the hex of its characters ("3A 30 31 30 33 ... 0D 0A"):
// hex whose first byte is ':' (0x3A) is that frame's bytes, not frame text starting with '3'.
bool isAsciiFrameAsHex(const HexTextResult &parsed)
{
    return parsed.ok && parsed.bytes.startsWith(':');
}

bool readFrame(const QString &text, Framing framing, const QString &what, QByteArray &bytes, QTextStream &err)
{
    const bool startsWithColon = text.trimmed().startsWith(QLatin1Char(':'));
    if (startsWithColon && (framing == Framing::Ascii || framing == Framing::Auto)) {
        bytes = asciiFrameFromText(text);
        return true;
    }
    const HexTextResult parsed = HexText::parse(text);
    if (framing == Framing::Ascii) {
        bytes = isAsciiFrameAsHex(parsed) ? parsed.bytes : asciiFrameFromText(text);
        return true;
    }
    if (!parsed.ok) {
        err << "mbscope decode: " << what << ": " << parsed.error.message << '\n';
        const QStringList lines = text.split(QLatin1Char('\n'));
        if (parsed.error.line >= 1 && parsed.error.line <= lines.size()) {
            err << "  " << lines.at(parsed.error.line - 1) << '\n'
                << "  " << QString(qMax(0, parsed.error.column - 1), QLatin1Char(' ')) << "^\n";
        }
        return false;
    }
    bytes = parsed.bytes;
    return true;
}

} // namespace

int runDecode(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Explains a Modbus frame field by field: offset, bytes, value, meaning and every problem found.\n"
        "The frame is given as hex (\"01 03 00 79 00 16 15 DD\", \"0x01,0x03\", \"01-03\"...) in the arguments or on "
        "standard input; an ASCII frame as its characters (\":070300C800042A\") or as the hex of its characters "
        "(\"3A 30 37 30 33 ... 0D 0A\", as a serial analyser shows it).\n"
        "Examples:\n"
        "  mbscope decode 01 03 00 79 00 16 15 DD\n"
        "  mbscope decode --request \"01 03 00 79 00 02 15 D2\" 01 03 04 04 1A 00 00 DA C4\n"
        "Exit status: 0 valid frame, 1 frame with errors, 2 unusable input."));
    parser.addHelpOption();
    const QCommandLineOption framingOpt(QStringLiteral("framing"),
                                        QStringLiteral("auto, rtu, ascii, tcp, udp or pdu (default auto)."),
                                        QStringLiteral("framing"), QStringLiteral("auto"));
    const QCommandLineOption directionOpt(QStringLiteral("direction"),
                                          QStringLiteral("auto, request or response (default auto)."),
                                          QStringLiteral("direction"), QStringLiteral("auto"));
    const QCommandLineOption requestOpt(QStringLiteral("request"),
                                        QStringLiteral("The matching request, in the same framing: the answer is checked against it."),
                                        QStringLiteral("hex"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the field tree as JSON."));
    parser.addOptions({framingOpt, directionOpt, requestOpt, jsonOpt});
    parser.addPositionalArgument(QStringLiteral("hex"), QStringLiteral("The frame's bytes (or read from standard input)."),
                                 QStringLiteral("[hex...]"));
    if (!parser.parse(arguments)) {
        err << "mbscope decode: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "decode");
        return ExitOk;
    }

    DissectOptions options;
    const auto framing = framingFromName(parser.value(framingOpt));
    if (!framing) {
        err << "mbscope decode: --framing '" << parser.value(framingOpt)
            << "' is not a framing; expected auto, rtu, ascii, tcp, udp or pdu\n";
        return ExitUsage;
    }
    const auto direction = directionFromName(parser.value(directionOpt));
    if (!direction) {
        err << "mbscope decode: --direction '" << parser.value(directionOpt)
            << "' is not a direction; expected auto, request or response\n";
        return ExitUsage;
    }
    options.framing = *framing;
    options.direction = *direction;

    QString text = parser.positionalArguments().join(QLatin1Char(' '));
    if (text.trimmed().isEmpty()) {
        QFile in;
        if (!in.open(stdin, QIODevice::ReadOnly)) {
            err << "mbscope decode: no frame given and standard input cannot be read\n";
            return ExitUsage;
        }
        text = QString::fromUtf8(in.readAll());
    }
    if (text.trimmed().isEmpty()) {
        err << "mbscope decode: no frame given: pass its bytes as hex, e.g. mbscope decode 01 03 00 79 00 16 15 DD\n";
        return ExitUsage;
    }
    QByteArray frame;
    if (!readFrame(text, options.framing, QStringLiteral("frame"), frame, err))
        return ExitUsage;
    if (parser.isSet(requestOpt)) {
        const Framing requestFraming = options.framing == Framing::Auto
                                           ? (frame.startsWith(':') ? Framing::Ascii : Framing::Auto)
                                           : options.framing;
        if (!readFrame(parser.value(requestOpt), requestFraming, QStringLiteral("--request"), options.request, err))
            return ExitUsage;
    }

    const Dissection d = Dissector::dissect(frame, options);
    if (parser.isSet(jsonOpt))
        out << QJsonDocument(DissectionFormat::toJson(d)).toJson(QJsonDocument::Indented);
    else
        out << DissectionFormat::toTable(d);
    return d.isValid() ? ExitOk : ExitFailure;
}

} // namespace mbscope::app
