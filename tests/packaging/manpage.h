#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testpackaging {

// A man page's roff source read the way the test needs it: its sections as plain text and the
// tags of its .TP items ("--framing framing"), with the font and character escapes removed and
// the alternating-font macros (.BR, .BI ...) joined as troff joins them. Enough for mbscope.1,
// not a roff interpreter.
class ManPage
{
public:
    struct Section {
        QString heading;    // "COMMANDS", "TARGET OPTIONS"
        QString subheading; // "decode" inside COMMANDS (.SS), empty before the first .SS
        QString text;       // plain text of every line in it
        QStringList tags;   // the .TP tags, one per item
    };

    [[nodiscard]] static ManPage parse(const QString &roff);

    [[nodiscard]] const QList<Section> &sections() const { return m_sections; }
    // The .SS names under heading, in order.
    [[nodiscard]] QStringList subsections(const QString &heading) const;
    // The section heading/subheading (nullptr when there is none).
    [[nodiscard]] const Section *section(const QString &heading, const QString &subheading = {}) const;
    // The .TH line's fields: name, section, date, source ("mbscope 0.1.0"), manual.
    [[nodiscard]] QStringList titleFields() const { return m_title; }
    [[nodiscard]] QString plainText() const;

    // One line of roff as plain text: a macro line's arguments joined, escapes removed; a request
    // that prints nothing (.PP, .RS ...) gives an empty string.
    [[nodiscard]] static QString plainLine(const QString &line);
    // A macro line's arguments, with "quoted arguments" kept whole.
    [[nodiscard]] static QStringList macroArguments(const QString &line);
    [[nodiscard]] static QString removeEscapes(QString text);

private:
    QList<Section> m_sections;
    QStringList m_title;
};

} // namespace mbscope::testpackaging
