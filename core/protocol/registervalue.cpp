#include "registervalue.h"

#include "hexformat.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

constexpr quint64 widthMask(int bits)
{
    return bits >= 64 ? ~quint64(0) : (quint64(1) << bits) - 1;
}

constexpr quint16 swapBytes(quint16 w)
{
    return quint16((w << 8) | (w >> 8));
}

int widthBits(RegisterFormat format)
{
    return 16 * format.registerCount();
}

QString quoted(QStringView text)
{
    return QLatin1Char('\'') + text.toString() + QLatin1Char('\'');
}

// The range of a type as a user types it, for messages.
QString rangeText(RegisterFormat format)
{
    const int bits = widthBits(format);
    if (format.isSigned()) {
        const qint64 max = qint64(widthMask(bits - 1));
        return QString::number(-max - 1) + QLatin1String(" to ") + QString::number(max);
    }
    return QLatin1String("0 to ") + QString::number(widthMask(bits));
}

RegisterValueResult failed(QString why)
{
    RegisterValueResult result;
    result.error = std::move(why);
    return result;
}

// A whole number in decimal, as QString::number gives it, at a fraction of its cost: the value
// text of every register a watch or a poll reads is made here, thousands of times a second.
QString decimalText(quint64 magnitude, bool negative)
{
    char16_t digits[21];
    int at = 21;
    do {
        digits[--at] = char16_t(u'0' + magnitude % 10);
        magnitude /= 10;
    } while (magnitude != 0);
    if (negative)
        digits[--at] = u'-';
    return QString(reinterpret_cast<const QChar *>(digits + at), 21 - at);
}

template <typename Float>
QString floatText(Float value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("Inf") : QStringLiteral("-Inf");
    // std::to_chars without a precision gives the shortest text that reads back to the same value
    // of that type, so float 123.456 shows as 123.456, not as the double 123.45600128173828.
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec != std::errc())
        return QStringLiteral("NaN");
    return QString::fromLatin1(buffer, end - buffer);
}

void appendEscaped(QString &out, quint8 byte)
{
    if (byte == '\\') {
        out += QLatin1String("\\\\");
    } else if (byte >= 0x20 && byte <= 0x7E) {
        out += QLatin1Char(char(byte));
    } else {
        out += QLatin1String("\\x") + hexDigits(byte, 2);
    }
}

// Reads text with \\ and \xNN escapes into bytes; characters must be ASCII (below 0x80).
bool decodeAscii(QStringView text, QByteArray *bytes, QString *error)
{
    bytes->reserve(text.size());
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        const int position = int(i) + 1;
        if (c.unicode() > 0x7F) {
            *error = QStringLiteral("character %1 (U+%2) is not ASCII; write a byte above 0x7F as \\xNN")
                         .arg(position)
                         .arg(hexDigits(c.unicode(), 4));
            return false;
        }
        if (c != u'\\') {
            bytes->append(char(c.unicode()));
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == u'\\') {
            bytes->append('\\');
            ++i;
            continue;
        }
        if (i + 3 < text.size() && (text[i + 1] == u'x' || text[i + 1] == u'X') && hexDigitValue(text[i + 2]) >= 0
            && hexDigitValue(text[i + 3]) >= 0) {
            bytes->append(char(hexDigitValue(text[i + 2]) * 16 + hexDigitValue(text[i + 3])));
            i += 3;
            continue;
        }
        *error = QStringLiteral("the backslash at character %1 starts no escape; write \\\\ for a backslash "
                                "or \\xNN (two hex digits) for a byte")
                     .arg(position);
        return false;
    }
    return true;
}

enum class Pattern { Ok, NoDigits, BadDigit, TooWide };

// A raw bit pattern in base 16 or 2, '_' allowed between digits.
Pattern parsePattern(QStringView digits, int base, int bits, quint64 *value, QChar *bad)
{
    const int shift = base == 16 ? 4 : 1;
    quint64 v = 0;
    bool any = false;
    for (QChar c : digits) {
        if (c == u'_')
            continue;
        const int d = hexDigitValue(c);
        if (d < 0 || d >= base) {
            *bad = c;
            return Pattern::BadDigit;
        }
        if (v >> (64 - shift))
            return Pattern::TooWide;
        v = (v << shift) | quint64(d);
        any = true;
    }
    if (!any)
        return Pattern::NoDigits;
    if ((v & ~widthMask(bits)) != 0)
        return Pattern::TooWide;
    *value = v;
    return Pattern::Ok;
}

RegisterValueResult patternFromText(QStringView whole, QStringView digits, int base, RegisterFormat format)
{
    quint64 value = 0;
    QChar bad;
    switch (parsePattern(digits, base, widthBits(format), &value, &bad)) {
    case Pattern::Ok:
        return {RegisterValue::fromBits(value, format), QString(), true};
    case Pattern::NoDigits:
        return failed(quoted(whole) + QLatin1String(" has no digits"));
    case Pattern::BadDigit:
        return failed(quoted(whole) + QLatin1String(": '") + bad
                      + (base == 16 ? QLatin1String("' is not a hex digit") : QLatin1String("' is not a binary digit")));
    case Pattern::TooWide:
        break;
    }
    return failed(quoted(whole) + QStringLiteral(" does not fit in the %1 bits of %2")
                                      .arg(widthBits(format))
                                      .arg(format.typeName()));
}

RegisterValueResult integerFromText(QStringView text, RegisterFormat format)
{
    if (text.size() > 2 && text[0] == u'0' && (text[1] == u'x' || text[1] == u'X'))
        return patternFromText(text, text.sliced(2), 16, format);
    if (text.size() > 2 && text[0] == u'0' && (text[1] == u'b' || text[1] == u'B'))
        return patternFromText(text, text.sliced(2), 2, format);

    const bool negative = text.startsWith(u'-');
    const QStringView digits = (negative || text.startsWith(u'+')) ? text.sliced(1) : text;
    bool wellFormed = !digits.isEmpty();
    for (QChar c : digits)
        wellFormed = wellFormed && c >= u'0' && c <= u'9';
    if (!wellFormed) {
        return failed(quoted(text) + QLatin1String(" is not a whole number: ") + format.typeName()
                      + QLatin1String(" takes decimal digits with an optional sign, or a 0x or 0b bit pattern"));
    }
    quint64 magnitude = 0;
    bool overflow = false;
    for (QChar c : digits) {
        const quint64 d = quint64(c.unicode() - u'0');
        if (magnitude > (std::numeric_limits<quint64>::max() - d) / 10) {
            overflow = true;
            break;
        }
        magnitude = magnitude * 10 + d;
    }
    const int bits = widthBits(format);
    bool inRange = !overflow;
    if (format.isSigned())
        inRange = inRange && magnitude <= (negative ? widthMask(bits - 1) + 1 : widthMask(bits - 1));
    else
        inRange = inRange && (negative ? magnitude == 0 : magnitude <= widthMask(bits));
    if (!inRange) {
        return failed(quoted(text) + QLatin1String(" is out of range for ") + format.typeName()
                      + QLatin1String(" (") + rangeText(format) + QLatin1Char(')'));
    }
    const quint64 value = negative ? quint64(0) - magnitude : magnitude;
    return {RegisterValue::fromBits(value, format), QString(), true};
}

template <typename Float>
RegisterValueResult floatFromText(QStringView text, RegisterFormat format)
{
    const QString lower = text.toString().toLower();
    const bool negative = lower.startsWith(QLatin1Char('-'));
    const QStringView body = (negative || lower.startsWith(QLatin1Char('+'))) ? QStringView(lower).sliced(1)
                                                                               : QStringView(lower);
    Float value = 0;
    if (body == QLatin1String("nan")) {
        value = std::numeric_limits<Float>::quiet_NaN();
    } else if (body == QLatin1String("inf") || body == QLatin1String("infinity")) {
        value = std::numeric_limits<Float>::infinity();
    } else {
        // from_chars would take a second sign ("--5"), so the body must start with a digit or point.
        bool plain = !body.isEmpty() && ((body[0] >= u'0' && body[0] <= u'9') || body[0] == u'.');
        for (QChar c : body) {
            plain = plain && ((c >= u'0' && c <= u'9') || c == u'.' || c == u'e' || c == u'+' || c == u'-');
        }
        const QByteArray latin = body.toLatin1();
        std::errc ec = std::errc::invalid_argument;
        if (plain) {
            const auto parsed = std::from_chars(latin.constData(), latin.constData() + latin.size(), value,
                                                std::chars_format::general);
            ec = parsed.ptr == latin.constData() + latin.size() ? parsed.ec : std::errc::invalid_argument;
        }
        if (ec == std::errc::result_out_of_range) {
            // Too large or too small? Ask a wider type; past even its range, the exponent's sign says.
            long double wide = 0;
            const auto w = std::from_chars(latin.constData(), latin.constData() + latin.size(), wide,
                                           std::chars_format::general);
            const bool small = w.ec == std::errc() ? std::fabs(wide) < 1 : latin.contains("e-");
            if (small) {
                return failed(quoted(text) + QLatin1String(" is too small for ") + format.typeName()
                              + QLatin1String(": it would round to 0 (the smallest nonzero value is ")
                              + floatText(std::numeric_limits<Float>::denorm_min()) + QLatin1Char(')'));
            }
            return failed(quoted(text) + QLatin1String(" is out of range for ") + format.typeName()
                          + QLatin1String(" (the largest finite value is ")
                          + floatText(std::numeric_limits<Float>::max()) + QLatin1Char(')'));
        }
        if (ec != std::errc()) {
            return failed(quoted(text) + QLatin1String(" is not a number: ") + format.typeName()
                          + QLatin1String(" takes decimal or scientific notation (123.456, -1.5e3), NaN or Inf"));
        }
    }
    if (negative)
        value = -value;
    using Bits = std::conditional_t<sizeof(Float) == 4, quint32, quint64>;
    return {RegisterValue::fromBits(std::bit_cast<Bits>(value), format), QString(), true};
}

} // namespace

RegisterValue::RegisterValue(quint64 bits, RegisterFormat format)
    : m_bits(bits & widthMask(widthBits(format))), m_format(format)
{
}

RegisterValueResult RegisterValue::fromRegisters(std::span<const quint16> registers, RegisterFormat format)
{
    const int needed = format.registerCount();
    if (registers.size() < size_t(needed)) {
        return failed(QStringLiteral("%1 needs %2, %3 given")
                          .arg(format.name())
                          .arg(needed == 1 ? QStringLiteral("1 register") : QStringLiteral("%1 registers").arg(needed))
                          .arg(qulonglong(registers.size())));
    }
    return {RegisterValue(joinRegisters(registers.first(size_t(needed)), format.order()), format), QString(), true};
}

RegisterValue RegisterValue::fromBits(quint64 bits, RegisterFormat format)
{
    return RegisterValue(bits, format);
}

RegisterValueResult RegisterValue::fromText(QStringView text, RegisterFormat format)
{
    // Spaces are characters in ASCII; everywhere else they only surround the number.
    if (format.type() == RegisterType::Ascii) {
        QByteArray bytes;
        QString error;
        if (!decodeAscii(text, &bytes, &error))
            return failed(quoted(text) + QLatin1String(": ") + error);
        if (bytes.isEmpty() || bytes.size() > 2) {
            return failed(quoted(text) + QStringLiteral(" is %1 characters; one register holds one or two")
                                             .arg(bytes.size()));
        }
        const quint64 bits = (quint64(quint8(bytes[0])) << 8) | (bytes.size() > 1 ? quint8(bytes[1]) : 0);
        return {RegisterValue(bits, format), QString(), true};
    }

    const QStringView trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return failed(QLatin1String("no value given for ") + format.typeName());
    switch (format.type()) {
    case RegisterType::Hex16: {
        const bool prefixed = trimmed.size() >= 2 && trimmed[0] == u'0' && (trimmed[1] == u'x' || trimmed[1] == u'X');
        return patternFromText(trimmed, prefixed ? trimmed.sliced(2) : trimmed, 16, format);
    }
    case RegisterType::Binary16: {
        const bool prefixed = trimmed.size() >= 2 && trimmed[0] == u'0' && (trimmed[1] == u'b' || trimmed[1] == u'B');
        return patternFromText(trimmed, prefixed ? trimmed.sliced(2) : trimmed, 2, format);
    }
    case RegisterType::Float32:
        return floatFromText<float>(trimmed, format);
    case RegisterType::Float64:
        return floatFromText<double>(trimmed, format);
    default:
        return integerFromText(trimmed, format);
    }
}

RegisterValueResult RegisterValue::fromSigned(qint64 value, RegisterFormat format)
{
    if (format.type() == RegisterType::Float32)
        return {RegisterValue(std::bit_cast<quint32>(float(value)), format), QString(), true};
    if (format.type() == RegisterType::Float64)
        return {RegisterValue(std::bit_cast<quint64>(double(value)), format), QString(), true};
    const int bits = widthBits(format);
    const bool inRange = format.isSigned()
        ? (bits == 64 || (value >= -qint64(widthMask(bits - 1)) - 1 && value <= qint64(widthMask(bits - 1))))
        : (value >= 0 && quint64(value) <= widthMask(bits));
    if (!inRange) {
        return failed(QString::number(value) + QLatin1String(" is out of range for ") + format.typeName()
                      + QLatin1String(" (") + rangeText(format) + QLatin1Char(')'));
    }
    return {RegisterValue(quint64(value), format), QString(), true};
}

RegisterValueResult RegisterValue::fromUnsigned(quint64 value, RegisterFormat format)
{
    if (format.type() == RegisterType::Float32)
        return {RegisterValue(std::bit_cast<quint32>(float(value)), format), QString(), true};
    if (format.type() == RegisterType::Float64)
        return {RegisterValue(std::bit_cast<quint64>(double(value)), format), QString(), true};
    const int bits = widthBits(format);
    if (value > (format.isSigned() ? widthMask(bits - 1) : widthMask(bits))) {
        return failed(QString::number(value) + QLatin1String(" is out of range for ") + format.typeName()
                      + QLatin1String(" (") + rangeText(format) + QLatin1Char(')'));
    }
    return {RegisterValue(value, format), QString(), true};
}

RegisterValueResult RegisterValue::fromDouble(double value, RegisterFormat format)
{
    const QString shown = floatText(value);
    if (format.type() == RegisterType::Float64)
        return {RegisterValue(std::bit_cast<quint64>(value), format), QString(), true};
    if (format.type() == RegisterType::Float32) {
        float narrow = 0;
        if (!std::isfinite(value)) {
            narrow = float(value);
        } else {
            // Halfway between FLT_MAX and the next power, IEEE rounds to infinity (ties to even);
            // below that a value rounds to FLT_MAX. Converting beyond range is undefined in C++.
            const double limit = std::ldexp(double(0x1FFFFFF), 103); // 0x1.ffffffp127
            const double magnitude = std::fabs(value);
            if (magnitude >= limit) {
                return failed(shown + QLatin1String(" is out of range for f32 (the largest finite value is ")
                              + floatText(std::numeric_limits<float>::max()) + QLatin1Char(')'));
            }
            narrow = magnitude > double(std::numeric_limits<float>::max())
                ? std::copysign(std::numeric_limits<float>::max(), float(value))
                : float(value);
            if (narrow == 0 && value != 0) {
                return failed(shown + QLatin1String(" is too small for f32: it would round to 0 (the smallest "
                                                    "nonzero value is ")
                              + floatText(std::numeric_limits<float>::denorm_min()) + QLatin1Char(')'));
            }
        }
        return {RegisterValue(std::bit_cast<quint32>(narrow), format), QString(), true};
    }

    if (!std::isfinite(value))
        return failed(shown + QLatin1String(" cannot be stored in ") + format.typeName()
                      + QLatin1String(": only float formats hold NaN and infinity"));
    if (std::trunc(value) != value)
        return failed(shown + QLatin1String(" is not a whole number: ") + format.typeName()
                      + QLatin1String(" holds whole numbers only"));
    const int bits = widthBits(format);
    const double low = format.isSigned() ? -std::ldexp(1.0, bits - 1) : 0.0;
    const double high = std::ldexp(1.0, format.isSigned() ? bits - 1 : bits); // exclusive
    if (value < low || value >= high) {
        return failed(shown + QLatin1String(" is out of range for ") + format.typeName() + QLatin1String(" (")
                      + rangeText(format) + QLatin1Char(')'));
    }
    const quint64 raw = format.isSigned() ? quint64(qint64(value)) : quint64(value);
    return {RegisterValue(raw, format), QString(), true};
}

qint64 RegisterValue::toInt64() const
{
    if (!m_format.isSigned())
        return qint64(m_bits);
    const int bits = widthBits(m_format);
    const quint64 sign = quint64(1) << (bits - 1);
    return qint64((m_bits ^ sign) - sign);
}

double RegisterValue::toDouble() const
{
    switch (m_format.type()) {
    case RegisterType::Float32:
        return double(std::bit_cast<float>(quint32(m_bits)));
    case RegisterType::Float64:
        return std::bit_cast<double>(m_bits);
    default:
        return m_format.isSigned() ? double(toInt64()) : double(m_bits);
    }
}

bool RegisterValue::isNaN() const
{
    return m_format.isFloat() && std::isnan(toDouble());
}

QString RegisterValue::toText() const
{
    switch (m_format.type()) {
    case RegisterType::Hex16:
        return hex(m_bits, 4);
    case RegisterType::Binary16: {
        QString out = QStringLiteral("0b");
        for (int bit = 15; bit >= 0; --bit) {
            out += (m_bits >> bit) & 1 ? QLatin1Char('1') : QLatin1Char('0');
            if (bit % 4 == 0 && bit > 0)
                out += QLatin1Char('_');
        }
        return out;
    }
    case RegisterType::Ascii: {
        QString out;
        appendEscaped(out, quint8(m_bits >> 8));
        appendEscaped(out, quint8(m_bits));
        return out;
    }
    case RegisterType::Float32:
        return floatText(std::bit_cast<float>(quint32(m_bits)));
    case RegisterType::Float64:
        return floatText(std::bit_cast<double>(m_bits));
    default:
        if (m_format.isSigned()) {
            const qint64 v = toInt64();
            // The magnitude of the most negative number does not fit a qint64: take it unsigned.
            return decimalText(v < 0 ? 0 - quint64(v) : quint64(v), v < 0);
        }
        return decimalText(m_bits, false);
    }
}

QList<quint16> RegisterValue::registers() const
{
    QList<quint16> out(m_format.registerCount(), 0);
    writeRegisters(std::span<quint16>(out.data(), size_t(out.size())));
    return out;
}

void RegisterValue::writeRegisters(std::span<quint16> out) const
{
    quint16 words[4] = {};
    const auto count = size_t(m_format.registerCount());
    splitRegisters(m_bits, m_format.order(), std::span<quint16>(words, count));
    for (size_t i = 0; i < count && i < out.size(); ++i)
        out[i] = words[i];
}

quint64 RegisterValue::joinRegisters(std::span<const quint16> registers, RegisterOrder order)
{
    const size_t n = std::min<size_t>(registers.size(), 4);
    const bool wordSwap = order == RegisterOrder::CDAB || order == RegisterOrder::DCBA;
    const bool byteSwap = order == RegisterOrder::BADC || order == RegisterOrder::DCBA;
    quint64 bits = 0;
    for (size_t k = 0; k < n; ++k) {
        const quint16 word = registers[wordSwap ? n - 1 - k : k];
        bits = (bits << 16) | (byteSwap ? swapBytes(word) : word);
    }
    return bits;
}

void RegisterValue::splitRegisters(quint64 bits, RegisterOrder order, std::span<quint16> out)
{
    const size_t n = std::min<size_t>(out.size(), 4);
    const bool wordSwap = order == RegisterOrder::CDAB || order == RegisterOrder::DCBA;
    const bool byteSwap = order == RegisterOrder::BADC || order == RegisterOrder::DCBA;
    for (size_t k = 0; k < n; ++k) {
        const auto word = quint16(bits >> (16 * (n - 1 - k)));
        out[wordSwap ? n - 1 - k : k] = byteSwap ? swapBytes(word) : word;
    }
}

QString RegisterValue::asciiText(std::span<const quint16> registers, bool byteSwapped)
{
    QString out;
    out.reserve(qsizetype(registers.size()) * 2);
    for (quint16 reg : registers) {
        const quint16 word = byteSwapped ? swapBytes(reg) : reg;
        appendEscaped(out, quint8(word >> 8));
        appendEscaped(out, quint8(word));
    }
    return out;
}

RegisterListResult RegisterValue::asciiRegisters(QStringView text, bool byteSwapped)
{
    RegisterListResult result;
    QByteArray bytes;
    if (!decodeAscii(text, &bytes, &result.error))
        return result;
    if (bytes.size() % 2 != 0)
        bytes.append('\0');
    result.registers.reserve(bytes.size() / 2);
    for (qsizetype i = 0; i < bytes.size(); i += 2) {
        const auto word = quint16((quint8(bytes[i]) << 8) | quint8(bytes[i + 1]));
        result.registers.append(byteSwapped ? swapBytes(word) : word);
    }
    result.ok = true;
    return result;
}

} // namespace mbscope
