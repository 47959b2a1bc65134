#pragma once

// The links and images of a Markdown file, as GitHub renders them: [text](target),
// ![alt](target) and <img src="target">, outside fenced code blocks and inline code; and the
// anchors its headings get (GitHub's slugs: lower case, punctuation dropped, spaces to hyphens).

#include <QtCore/QList>
#include <QtCore/QSet>
#include <QtCore/QString>

namespace mbscope::testdocs {

struct MarkdownLink {
    QString target; // as written, "images/first-run.png" or "guide.md#polling"
    int line = 0;   // 1-based
    bool image = false;
};

[[nodiscard]] QList<MarkdownLink> markdownLinks(const QString &text);
[[nodiscard]] QSet<QString> markdownAnchors(const QString &text);

} // namespace mbscope::testdocs
