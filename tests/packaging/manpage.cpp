#include "manpage.h"

#include <QtCore/QRegularExpression>

namespace mbscope::testpackaging {

namespace {

// Macros whose arguments alternate fonts and are printed without spaces between them.
bool isAlternating(const QString &macro)
{
    static const QStringList names{QStringLiteral("BR"), QStringLiteral("RB"), QStringLiteral("BI"),
                                   QStringLiteral("IB"), QStringLiteral("IR"), QStringLiteral("RI")};
    return names.contains(macro);
}

// Macros whose arguments are printed as text, separated by spaces.
bool isText(const QString &macro)
{
    static const QStringList names{QStringLiteral("B"), QStringLiteral("I"), QStringLiteral("SM"),
                                   QStringLiteral("SB"), QStringLiteral("SY"), QStringLiteral("OP")};
    return names.contains(macro);
}

} // namespace

QStringList ManPage::macroArguments(const QString &line)
{
    QStringList arguments;
    QString current;
    bool quoted = false;
    bool any = false;
    const qsizetype start = line.indexOf(QLatin1Char(' '));
    if (start < 0)
        return arguments;
    for (qsizetype i = start + 1; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (c == QLatin1Char('"')) {
            quoted = !quoted;
            any = true;
        } else if (c == QLatin1Char(' ') && !quoted) {
            if (any || !current.isEmpty())
                arguments.append(current);
            current.clear();
            any = false;
        } else if (c == QLatin1Char('\\') && i + 1 < line.size()) {
            current += c;
            current += line.at(++i);
        } else {
            current += c;
        }
    }
    if (any || !current.isEmpty())
        arguments.append(current);
    return arguments;
}

QString ManPage::removeEscapes(QString text)
{
    static const QRegularExpression fonts(QStringLiteral(R"(\\f(\[[^\]]*\]|\(..|.))"));
    text.remove(fonts);
    text.replace(QLatin1String("\\-"), QLatin1String("-"));
    text.replace(QLatin1String("\\(dq"), QLatin1String("\""));
    text.replace(QLatin1String("\\(lq"), QLatin1String("\""));
    text.replace(QLatin1String("\\(rq"), QLatin1String("\""));
    text.replace(QLatin1String("\\(en"), QLatin1String("-"));
    text.replace(QLatin1String("\\(em"), QLatin1String("-"));
    text.replace(QLatin1String("\\ "), QLatin1String(" "));
    text.remove(QLatin1String("\\&"));
    text.remove(QLatin1String("\\%"));
    text.replace(QLatin1String("\\e"), QLatin1String("\\"));
    return text;
}

QString ManPage::plainLine(const QString &line)
{
    if (!line.startsWith(QLatin1Char('.')) && !line.startsWith(QLatin1Char('\'')))
        return removeEscapes(line);
    const QString macro = line.mid(1).section(QLatin1Char(' '), 0, 0);
    const QStringList arguments = macroArguments(line);
    if (isAlternating(macro))
        return removeEscapes(arguments.join(QString()));
    if (isText(macro) || macro == QLatin1String("SH") || macro == QLatin1String("SS"))
        return removeEscapes(arguments.join(QLatin1Char(' ')));
    return {};
}

ManPage ManPage::parse(const QString &roff)
{
    ManPage page;
    Section *current = nullptr;
    bool tagNext = false;
    const QStringList lines = roff.split(QLatin1Char('\n'));
    for (const QString &line : lines) {
        if (line.startsWith(QLatin1String(".\\\"")) || line == QLatin1String("."))
            continue;
        if (line.startsWith(QLatin1String(".TH "))) {
            page.m_title = macroArguments(line);
            continue;
        }
        if (line.startsWith(QLatin1String(".SH "))) {
            page.m_sections.append({plainLine(line), {}, {}, {}});
            current = &page.m_sections.last();
            tagNext = false;
            continue;
        }
        if (line.startsWith(QLatin1String(".SS "))) {
            const QString heading = current ? current->heading : QString();
            page.m_sections.append({heading, plainLine(line), {}, {}});
            current = &page.m_sections.last();
            tagNext = false;
            continue;
        }
        if (!current)
            continue;
        if (line == QLatin1String(".TP")) {
            tagNext = true;
            continue;
        }
        const QString text = plainLine(line);
        if (tagNext) {
            current->tags.append(text.trimmed());
            tagNext = false;
        }
        if (!text.isEmpty())
            current->text += text + QLatin1Char('\n');
    }
    return page;
}

QStringList ManPage::subsections(const QString &heading) const
{
    QStringList names;
    for (const Section &s : m_sections) {
        if (s.heading == heading && !s.subheading.isEmpty())
            names.append(s.subheading);
    }
    return names;
}

const ManPage::Section *ManPage::section(const QString &heading, const QString &subheading) const
{
    for (const Section &s : m_sections) {
        if (s.heading == heading && s.subheading == subheading)
            return &s;
    }
    return nullptr;
}

QString ManPage::plainText() const
{
    QString text;
    for (const Section &s : m_sections)
        text += s.text;
    return text;
}

} // namespace mbscope::testpackaging
