#include "delimitedframer.h"

#include "hexformat.h"

namespace mbscope {

namespace {

// ASCII control character names (ANSI X3.4 / ISO 646), as protocol documents write them.
constexpr const char *kControlNames[32] = {
    "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT",  "LF",  "VT",  "FF",  "CR",  "SO",  "SI",
    "DLE", "DC1", "DC2", "DC3", "DC4", "NAK", "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US",
};

} // namespace

DelimitedFramer::DelimitedFramer(const DelimitedFraming &framing)
    : m_framing(framing)
{
    for (char c : framing.startBytes)
        m_isStart.set(quint8(c));
    for (char c : framing.endBytes)
        m_isEnd.set(quint8(c));
}

quint8 DelimitedFramer::checksum(DelimitedChecksum kind, QByteArrayView bytes)
{
    quint8 value = 0;
    switch (kind) {
    case DelimitedChecksum::None:
        break;
    case DelimitedChecksum::Sum:
        for (char c : bytes)
            value = quint8(value + quint8(c));
        break;
    case DelimitedChecksum::Xor:
        for (char c : bytes)
            value = quint8(value ^ quint8(c));
        break;
    }
    return value;
}

QByteArray DelimitedFramer::complete(const DelimitedFraming &framing, QByteArrayView frame)
{
    QByteArray out = frame.toByteArray();
    if (framing.checksum != DelimitedChecksum::None)
        out.append(char(checksum(framing.checksum, frame)));
    return out;
}

QString DelimitedFramer::toText(QByteArrayView bytes)
{
    QString text;
    text.reserve(bytes.size());
    for (char c : bytes) {
        const quint8 b = quint8(c);
        if (b < 32)
            text += QLatin1Char('<') + QLatin1String(kControlNames[b]) + QLatin1Char('>');
        else if (b == 0x7F)
            text += QLatin1String("<DEL>");
        else if (b > 0x7F)
            text += QLatin1String("\\x") + hexDigits(b, 2);
        else
            text += QLatin1Char(c);
    }
    return text;
}

QString DelimitedFramer::checksumName(DelimitedChecksum kind)
{
    switch (kind) {
    case DelimitedChecksum::None: return QStringLiteral("none");
    case DelimitedChecksum::Sum: return QStringLiteral("sum");
    case DelimitedChecksum::Xor: return QStringLiteral("xor");
    }
    return QStringLiteral("none");
}

void DelimitedFramer::process()
{
    const bool started = m_isStart.any();
    const qsizetype trailer = m_framing.checksum == DelimitedChecksum::None ? 0 : 1;
    auto isStart = [this](char c) { return m_isStart.test(quint8(c)); };
    for (;;) {
        const QByteArrayView bytes = pending();
        if (bytes.isEmpty())
            return;
        qsizetype first = 0;
        if (started) {
            if (!isStart(bytes[0])) {
                qsizetype at = 1;
                while (at < bytes.size() && !isStart(bytes[at]))
                    ++at;
                skip(at, SkipReason::NoFrameStart);
                m_scanned = 0;
                continue;
            }
            first = 1;
        }
        bool decided = false;
        for (qsizetype i = qMax(first, m_scanned); i < bytes.size() && !decided; ++i) {
            const char c = bytes[i];
            // The end bytes are tested first, so that a framing whose start and end bytes are the
            // same ('|' ... '|') still ends its frames.
            if (m_isEnd.test(quint8(c))) {
                if (bytes.size() < i + 1 + trailer) {
                    m_scanned = i; // the checksum byte has not arrived yet
                    return;
                }
                emitChecked(i + 1 + trailer);
                decided = true;
            } else if (started && isStart(c)) {
                skip(i, SkipReason::Abandoned);
                decided = true;
            } else if (i + 1 + trailer >= kMaxFrameSize) {
                skip(i + 1, SkipReason::TooLong);
                decided = true;
            }
        }
        if (!decided) {
            m_scanned = bytes.size();
            return;
        }
        m_scanned = 0;
    }
}

void DelimitedFramer::emitChecked(qsizetype length)
{
    if (m_framing.checksum == DelimitedChecksum::None) {
        emitFrame(length);
        return;
    }
    const QByteArrayView frame = pending().first(length);
    const quint8 expected = checksum(m_framing.checksum, frame.first(length - 1));
    const quint8 got = quint8(frame[length - 1]);
    if (got == expected) {
        emitFrame(length);
        return;
    }
    const QString how = m_framing.checksum == DelimitedChecksum::Sum ? QStringLiteral("8-bit sum (BCC)")
                                                                     : QStringLiteral("XOR");
    emitFrame(length, FrameStatus::Malformed,
              QStringLiteral("checksum %1 does not match %2, the %3 of the %4 bytes up to the end byte")
                  .arg(hexByte(got), hexByte(expected), how)
                  .arg(length - 1));
}

} // namespace mbscope
