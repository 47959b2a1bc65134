#include "common/progressline.h"

#include "common/jsonfailure.h"

#include <cstdio>

#ifdef Q_OS_UNIX
#include <sys/ioctl.h>
#include <unistd.h>
#endif

namespace mbscope::app {

namespace {

int terminalColumns()
{
#ifdef Q_OS_UNIX
    struct winsize size = {};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
        return size.ws_col;
#endif
    return 80;
}

} // namespace

ProgressLine::ProgressLine()
{
#ifdef Q_OS_UNIX
    m_enabled = JsonFailureReport::stderrWasTerminal();
#endif
}

ProgressLine::~ProgressLine()
{
    clear();
}

void ProgressLine::show(const QString &text)
{
    if (!m_enabled)
        return;
    // One column short of the width: some terminals wrap when the last column is written.
    const QString line = text.left(qMax(10, terminalColumns() - 1));
    std::fputs("\r\033[K", stderr);
    std::fputs(line.toLocal8Bit().constData(), stderr);
    std::fflush(stderr);
    m_shown = true;
}

void ProgressLine::clear()
{
    if (!m_enabled || !m_shown)
        return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    m_shown = false;
}

} // namespace mbscope::app
