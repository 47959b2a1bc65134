#include "scripthighlighter.h"

#include "common/severitystyle.h"

#include <QtCore/QRegularExpression>

namespace mbscope {

namespace {

// Block state: inside a /* */ comment that goes on to the next line.
constexpr int kInComment = 1;

const QRegularExpression &keywords()
{
    static const QRegularExpression re(QStringLiteral(
        "\\b(?:break|case|catch|class|const|continue|debugger|default|delete|do|else|export|extends|false|finally|for|"
        "function|if|import|in|instanceof|let|new|null|of|return|super|switch|this|throw|true|try|typeof|undefined|var|"
        "void|while|with|yield)\\b"));
    return re;
}

const QRegularExpression &numbers()
{
    static const QRegularExpression re(
        QStringLiteral("\\b(?:0[xX][0-9A-Fa-f]+|0[bB][01]+|\\d+(?:\\.\\d*)?(?:[eE][+-]?\\d+)?)\\b"));
    return re;
}

} // namespace

ScriptHighlighter::ScriptHighlighter(QTextDocument *document)
    : QSyntaxHighlighter(document)
{
}

QTextCharFormat ScriptHighlighter::format(Kind kind)
{
    QTextCharFormat f;
    switch (kind) {
    case Kind::Keyword:
        f.setForeground(SeverityStyle::textColor(Severity::Info));
        f.setFontWeight(QFont::Bold);
        break;
    case Kind::String: f.setForeground(SeverityStyle::goodColor()); break;
    case Kind::Number: f.setForeground(SeverityStyle::textColor(Severity::Warning)); break;
    case Kind::Comment:
        f.setForeground(SeverityStyle::mutedColor());
        f.setFontItalic(true);
        break;
    }
    return f;
}

void ScriptHighlighter::highlightBlock(const QString &text)
{
    setCurrentBlockState(0);
    const qsizetype n = text.size();
    // Where strings and comments are: keywords and numbers are not looked for inside them.
    std::vector<bool> taken(std::size_t(n), false);
    auto mark = [&](qsizetype from, qsizetype length, Kind kind) {
        setFormat(int(from), int(length), format(kind));
        for (qsizetype k = from; k < from + length && k < n; ++k)
            taken[std::size_t(k)] = true;
    };
    qsizetype i = 0;
    if (previousBlockState() == kInComment) {
        const qsizetype end = text.indexOf(QLatin1String("*/"));
        if (end < 0) {
            mark(0, n, Kind::Comment);
            setCurrentBlockState(kInComment);
            return;
        }
        mark(0, end + 2, Kind::Comment);
        i = end + 2;
    }
    while (i < n) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('/') && i + 1 < n && text.at(i + 1) == QLatin1Char('/')) {
            mark(i, n - i, Kind::Comment);
            break;
        }
        if (c == QLatin1Char('/') && i + 1 < n && text.at(i + 1) == QLatin1Char('*')) {
            const qsizetype end = text.indexOf(QLatin1String("*/"), i + 2);
            if (end < 0) {
                mark(i, n - i, Kind::Comment);
                setCurrentBlockState(kInComment);
                break;
            }
            mark(i, end + 2 - i, Kind::Comment);
            i = end + 2;
            continue;
        }
        if (c == QLatin1Char('"') || c == QLatin1Char('\'') || c == QLatin1Char('`')) {
            qsizetype j = i + 1;
            while (j < n && text.at(j) != c)
                j += text.at(j) == QLatin1Char('\\') ? 2 : 1;
            const qsizetype end = std::min(j + 1, n);
            mark(i, end - i, Kind::String);
            i = end;
            continue;
        }
        ++i;
    }
    for (const QRegularExpression *re : {&keywords(), &numbers()}) {
        const Kind kind = re == &keywords() ? Kind::Keyword : Kind::Number;
        for (auto it = re->globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            if (!taken[std::size_t(m.capturedStart())])
                setFormat(int(m.capturedStart()), int(m.capturedLength()), format(kind));
        }
    }
}

} // namespace mbscope
