#include "helptext.h"

#include <QtCore/QRegularExpression>

namespace mbscope::testpackaging {

namespace {

// The lines of the block under a heading ("Options:"), up to the next unindented line.
QStringList block(const QString &help, const QString &heading)
{
    QStringList lines;
    bool inside = false;
    for (const QString &line : help.split(QLatin1Char('\n'))) {
        if (line.trimmed() == heading) {
            inside = true;
            continue;
        }
        if (!inside)
            continue;
        if (!line.isEmpty() && !line.startsWith(QLatin1Char(' ')))
            break;
        lines.append(line);
    }
    return lines;
}

} // namespace

QList<HelpOption> helpOptions(const QString &help)
{
    // "  -h, --help", "  --framing <framing>", "  -v, --verbose"; continuation lines are indented
    // further and so never match.
    static const QRegularExpression optionLine(
        QStringLiteral(R"(^  (?:-([A-Za-z0-9?]))?(?:, )?(?:--([A-Za-z0-9][A-Za-z0-9-]*))?(?: <([^>]+)>)?(?:\s|$))"));
    QList<HelpOption> options;
    for (const QString &line : block(help, QStringLiteral("Options:"))) {
        if (!line.startsWith(QLatin1String("  -")))
            continue;
        const QRegularExpressionMatch m = optionLine.match(line);
        if (!m.hasMatch())
            continue;
        const QString name = m.captured(2).isEmpty() ? m.captured(1) : m.captured(2);
        if (!name.isEmpty())
            options.append({name, m.captured(3), m.captured(2).isEmpty() ? QString() : m.captured(1)});
    }
    return options;
}

QStringList helpSubcommands(const QString &help)
{
    static const QRegularExpression commandLine(QStringLiteral(R"(^  ([a-z][a-z0-9-]*)\s{2,}\S)"));
    QStringList names;
    for (const QString &line : block(help, QStringLiteral("Subcommands:"))) {
        const QRegularExpressionMatch m = commandLine.match(line);
        if (m.hasMatch())
            names.append(m.captured(1));
    }
    return names;
}

} // namespace mbscope::testpackaging
