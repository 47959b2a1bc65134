#include "cli.h"

namespace mbscope::app {

QString subcommandHelp(const QString &helpText, const char *name)
{
    const qsizetype end = helpText.indexOf(QLatin1Char('\n'));
    if (!helpText.startsWith(QLatin1String("Usage: ")) || end < 0)
        return helpText;
    return QStringLiteral("Usage: mbscope %1 [options]").arg(QLatin1String(name)) + helpText.mid(end);
}

} // namespace mbscope::app
