#pragma once

#include <QtGui/QSyntaxHighlighter>

namespace mbscope {

// JavaScript in the Script tab's editor: keywords, strings (also template strings on one line),
// numbers and comments (// and /* */ over several lines), in the theme's colours
// (SeverityStyle: info blue keywords, green strings, amber numbers, grey comments), read from
// the application palette each time a block is coloured, so light and dark both read well.
// Call rehighlight() when the theme changes.
class ScriptHighlighter : public QSyntaxHighlighter
{
    Q_OBJECT
public:
    enum class Kind { Keyword, String, Number, Comment };

    explicit ScriptHighlighter(QTextDocument *document);

    // The format of a kind of token under the current palette.
    [[nodiscard]] static QTextCharFormat format(Kind kind);

protected:
    void highlightBlock(const QString &text) override;
};

} // namespace mbscope
