#include "cli.h"

namespace mbscope::app {

QString subcommandHelp(const QString &helpText, const char *name)
{
    const qsizetype end = helpText.indexOf(QLatin1Char('\n'));
    if (!helpText.startsWith(QLatin1String("Usage: ")) || end < 0)
        return helpText;
    // QCommandLineParser writes "Usage: PROGRAM [options] ARGUMENTS": the positional arguments
    // after "[options]" stay (analyze's capture, export's source).
    const qsizetype options = helpText.left(end).indexOf(QLatin1String(" [options]"));
    const QString rest = options >= 0 ? helpText.mid(options, end - options) : QStringLiteral(" [options]");
    return QStringLiteral("Usage: mbscope %1").arg(QLatin1String(name)) + rest + helpText.mid(end);
}

} // namespace mbscope::app
