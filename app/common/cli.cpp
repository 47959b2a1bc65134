#include "common/cli.h"

#include <utility>

namespace mbscope::app {

namespace {
HelpCapture *activeCapture = nullptr;
QString withUsage(const QString &helpText, const char *name);
} // namespace

HelpCapture::HelpCapture()
    : m_previous(activeCapture)
{
    activeCapture = this;
}

HelpCapture::~HelpCapture()
{
    activeCapture = m_previous;
}

QString HelpCapture::take()
{
    return std::exchange(m_text, QString());
}

QString subcommandHelp(const QString &helpText, const char *name)
{
    QString text = withUsage(helpText, name);
    if (!activeCapture)
        return text;
    activeCapture->m_text += text;
    return {};
}

namespace {

QString withUsage(const QString &helpText, const char *name)
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

} // namespace

} // namespace mbscope::app
