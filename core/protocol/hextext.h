#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>
#include <QtCore/QStringView>

namespace mbscope {

// Where and why hex text could not be read. line and column are 1-based and count characters
// (QChar) in the text as the user typed it.
struct HexTextError {
    int line = 0;
    int column = 0;
    QString message; // "line 1, column 7: 'G' is not a hex digit" style text, self-contained
};

struct HexTextResult {
    QByteArray bytes;
    HexTextError error; // meaningful only when !ok
    bool ok = false;
};

// Hex text as people type it: "01 03 00 79 00 16 15 DD", "01030079001615DD", "0x01,0x03",
// "01-03", "01:03", mixed case, several lines. Every byte is exactly two hex digits, except after
// "0x", where one digit is accepted ("0x1"). Separators: spaces, tabs, newlines, ',', '-', ':', ';'.
//
// The text is read as groups between separators. A group is either a run of an even number of hex
// digits (one byte per pair, "01030079") or "0x"/"0X" followed by one or two hex digits (one byte).
// Anything else is refused at its first bad character: a stray character (reported where it is), a
// group with an odd number of digits or "0x" with no digit or more than two (reported at the
// group's first character). Newlines are LF, CR LF or a lone CR. Text without any byte is refused.
//
// format() writes "0x" in lower case in every case setting; only the digits follow `uppercase`.
// With bytesPerLine > 0, lines end with "\n" (after the separator "," in CArray style), and the
// result always parses back to the same bytes.
class HexText
{
public:
    enum class Style : quint8 {
        Spaced,  // 01 03 00 79
        Compact, // 01030079
        CArray,  // 0x01, 0x03, 0x00, 0x79
        Dashed,  // 01-03-00-79
        Colon,   // 01:03:00:79
    };

    struct FormatOptions {
        Style style = Style::Spaced;
        bool uppercase = true;
        int bytesPerLine = 0; // 0: all on one line
    };

    [[nodiscard]] static HexTextResult parse(QStringView text);
    [[nodiscard]] static QString format(QByteArrayView bytes, const FormatOptions &options);
    [[nodiscard]] static QString format(QByteArrayView bytes) { return format(bytes, FormatOptions{}); }
};

} // namespace mbscope
