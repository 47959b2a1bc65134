#include "hextext.h"

#include "hexformat.h"

namespace mbscope {

namespace {

// Longest group quoted verbatim in a message; longer ones are cut so a pasted megabyte of
// digits does not become a megabyte of message.
constexpr qsizetype kMaxQuoted = 24;

bool isSeparator(QChar c)
{
    switch (c.unicode()) {
    case u' ': case u'\t': case u'\n': case u'\r': case u',': case u'-': case u':': case u';':
        return true;
    default:
        return false;
    }
}

bool isPrefixX(QChar c)
{
    return c == u'x' || c == u'X';
}

QString quoted(QStringView group)
{
    if (group.size() <= kMaxQuoted)
        return QLatin1Char('\'') + group.toString() + QLatin1Char('\'');
    return QLatin1Char('\'') + group.first(kMaxQuoted).toString() + QLatin1String("...'");
}

// A bad character as the user would recognise it: printable ones quoted, others (controls,
// unusual spaces such as U+00A0 from a pasted web page) by code point, which a quote would hide.
QString describeCharacter(QStringView text, qsizetype at)
{
    const QChar c = text[at];
    if (c.isHighSurrogate() && at + 1 < text.size() && text[at + 1].isLowSurrogate()) {
        const char32_t ucs4 = QChar::surrogateToUcs4(c, text[at + 1]);
        return QLatin1Char('\'') + text.sliced(at, 2).toString() + QLatin1String("' (U+")
            + hexDigits(uint(ucs4), 4) + QLatin1Char(')');
    }
    const QString code = QLatin1String("U+")
        + hexDigits(c.unicode(), 4);
    if (c.isSpace())
        return code + QLatin1String(" (a space character other than space, tab or newline)");
    if (!c.isPrint())
        return code + QLatin1String(" (a control or unprintable character)");
    if (c.unicode() > 0x7E)
        return QLatin1Char('\'') + c + QLatin1String("' (") + code + QLatin1Char(')');
    return QLatin1Char('\'') + c + QLatin1Char('\'');
}

// Line bookkeeping shared by the scanner: 1-based line, index where the line starts.
struct Position {
    int line = 1;
    qsizetype lineStart = 0;
    [[nodiscard]] int column(qsizetype at) const { return int(at - lineStart) + 1; }
};

HexTextResult failure(const Position &pos, qsizetype at, const QString &why)
{
    HexTextResult result;
    result.error.line = pos.line;
    result.error.column = pos.column(at);
    result.error.message = QStringLiteral("line %1, column %2: %3")
                               .arg(result.error.line)
                               .arg(result.error.column)
                               .arg(why);
    return result;
}

HexTextResult strayCharacter(const Position &pos, QStringView text, qsizetype at)
{
    QString why = describeCharacter(text, at) + QLatin1String(" is not a hex digit or a separator");
    if (isPrefixX(text[at]))
        why += QLatin1String(" (0x may only start a byte, as in 0x01 0x03)");
    else
        why += QLatin1String(" (separators are space, tab, newline, ',', '-', ':' and ';')");
    return failure(pos, at, why);
}

} // namespace

HexTextResult HexText::parse(QStringView text)
{
    QByteArray bytes;
    bytes.reserve(text.size() / 2);
    Position pos;
    const qsizetype n = text.size();
    qsizetype i = 0;
    while (i < n) {
        const QChar c = text[i];
        if (isSeparator(c)) {
            // LF, CR LF and a lone CR each end one line; in CR LF the LF does the counting.
            const bool newline = c == u'\n' || (c == u'\r' && !(i + 1 < n && text[i + 1] == u'\n'));
            ++i;
            if (newline) {
                ++pos.line;
                pos.lineStart = i;
            }
            continue;
        }

        const qsizetype groupStart = i;
        if (c == u'0' && i + 1 < n && isPrefixX(text[i + 1])) {
            qsizetype j = i + 2;
            while (j < n && hexDigitValue(text[j]) >= 0)
                ++j;
            if (j < n && !isSeparator(text[j]))
                return strayCharacter(pos, text, j);
            const qsizetype digits = j - (i + 2);
            if (digits == 0) {
                return failure(pos, groupStart,
                               text.sliced(i, 2).toString()
                                   + QLatin1String(" is not followed by a hex digit; write a byte as 0x01 or 0x1"));
            }
            if (digits > 2) {
                return failure(pos, groupStart,
                               QStringLiteral("%1 has %2 hex digits after %3; a 0x prefix introduces one byte "
                                              "(one or two digits): write 0x01, 0x03 or 01 03")
                                   .arg(quoted(text.sliced(i, j - i)))
                                   .arg(digits)
                                   .arg(text.sliced(i, 2)));
            }
            int value = 0;
            for (qsizetype k = i + 2; k < j; ++k)
                value = value * 16 + hexDigitValue(text[k]);
            bytes.append(char(value));
            i = j;
            continue;
        }

        qsizetype j = i;
        while (j < n && hexDigitValue(text[j]) >= 0)
            ++j;
        if (j < n && !isSeparator(text[j]))
            return strayCharacter(pos, text, j);
        const qsizetype digits = j - i;
        if (digits % 2 != 0) {
            return failure(pos, groupStart,
                           QStringLiteral("%1 has an odd number of hex digits (%2); each byte needs two")
                               .arg(quoted(text.sliced(i, digits)))
                               .arg(digits));
        }
        for (qsizetype k = i; k < j; k += 2)
            bytes.append(char(hexDigitValue(text[k]) * 16 + hexDigitValue(text[k + 1])));
        i = j;
    }

    if (bytes.isEmpty()) {
        Position start;
        if (text.isEmpty())
            return failure(start, 0, QStringLiteral("the text is empty; type bytes as hex, e.g. 01 03 00 79"));
        return failure(start, 0, QStringLiteral("the text holds only separators and no hex byte; "
                                                "type bytes as hex, e.g. 01 03 00 79"));
    }
    HexTextResult result;
    result.bytes = std::move(bytes);
    result.ok = true;
    return result;
}

QString HexText::format(QByteArrayView bytes, const FormatOptions &options)
{
    const char *digits = options.uppercase ? "0123456789ABCDEF" : "0123456789abcdef";
    QLatin1String separator;
    QLatin1String lineBreak("\n");
    bool prefix = false;
    switch (options.style) {
    case Style::Spaced: separator = QLatin1String(" "); break;
    case Style::Compact: separator = QLatin1String(""); break;
    case Style::CArray:
        separator = QLatin1String(", ");
        lineBreak = QLatin1String(",\n");
        prefix = true;
        break;
    case Style::Dashed: separator = QLatin1String("-"); break;
    case Style::Colon: separator = QLatin1String(":"); break;
    }

    QString out;
    out.reserve(bytes.size() * ((prefix ? 4 : 2) + separator.size()));
    const qsizetype perLine = options.bytesPerLine > 0 ? options.bytesPerLine : bytes.size();
    for (qsizetype k = 0; k < bytes.size(); ++k) {
        if (k > 0)
            out += (k % perLine == 0) ? lineBreak : separator;
        if (prefix)
            out += QLatin1String("0x");
        const auto b = quint8(bytes[k]);
        out += QLatin1Char(digits[b >> 4]);
        out += QLatin1Char(digits[b & 0x0F]);
    }
    return out;
}

} // namespace mbscope
