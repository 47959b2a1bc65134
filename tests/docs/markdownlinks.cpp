#include "markdownlinks.h"

#include <QtCore/QHash>
#include <QtCore/QRegularExpression>
#include <QtCore/QStringList>

namespace mbscope::testdocs {

namespace {

// Lines outside ``` fences (fenced lines are emptied, so line numbers hold); with blankCode,
// `inline code` is blanked too, so that examples are not read as links.
QStringList proseLines(const QString &text, bool blankCode)
{
    static const QRegularExpression inlineCode(QStringLiteral("`[^`]*`"));
    QStringList lines = text.split(QLatin1Char('\n'));
    bool fenced = false;
    for (QString &line : lines) {
        if (line.trimmed().startsWith(QLatin1String("```"))) {
            fenced = !fenced;
            line.clear();
        } else if (fenced) {
            line.clear();
        } else if (blankCode) {
            line.replace(inlineCode, QStringLiteral("``"));
        }
    }
    return lines;
}

} // namespace

QList<MarkdownLink> markdownLinks(const QString &text)
{
    static const QRegularExpression link(QStringLiteral(R"re((!?)\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))re"));
    static const QRegularExpression img(QStringLiteral(R"re(<img\s[^>]*src="([^"]+)")re"));
    QList<MarkdownLink> links;
    const QStringList lines = proseLines(text, true);
    for (int i = 0; i < lines.size(); ++i) {
        for (auto it = link.globalMatch(lines.at(i)); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            links.append({m.captured(2), i + 1, !m.captured(1).isEmpty()});
        }
        for (auto it = img.globalMatch(lines.at(i)); it.hasNext();)
            links.append({it.next().captured(1), i + 1, true});
    }
    return links;
}

QSet<QString> markdownAnchors(const QString &text)
{
    static const QRegularExpression heading(QStringLiteral(R"(^#{1,6}\s+(.*?)\s*#*\s*$)"));
    static const QRegularExpression dropped(QStringLiteral(R"([^\p{L}\p{N}\s_-])"));
    QSet<QString> anchors;
    QHash<QString, int> seen;
    for (const QString &line : proseLines(text, false)) {
        const QRegularExpressionMatch m = heading.match(line);
        if (!m.hasMatch())
            continue;
        QString slug = m.captured(1).toLower().remove(dropped);
        slug.replace(QLatin1Char(' '), QLatin1Char('-'));
        // GitHub numbers repeated headings: intro, intro-1, intro-2.
        const int count = seen.value(slug);
        seen.insert(slug, count + 1);
        anchors.insert(count == 0 ? slug : QStringLiteral("%1-%2").arg(slug).arg(count));
    }
    return anchors;
}

} // namespace mbscope::testdocs
