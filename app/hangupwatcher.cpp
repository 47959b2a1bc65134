#include "hangupwatcher.h"

#include <QtCore/QSocketNotifier>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>
#endif

namespace mbscope::app {

#ifdef Q_OS_UNIX

namespace {

int s_pipe[2] = {-1, -1};
struct sigaction s_old;

void onSignal(int)
{
    const int saved = errno;
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(s_pipe[1], &byte, 1);
    errno = saved;
}

} // namespace

HangupWatcher::HangupWatcher(QObject *parent)
    : QObject(parent)
{
    if (::pipe2(s_pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
        s_pipe[0] = s_pipe[1] = -1;
        return;
    }
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGHUP, &action, &s_old);
    m_notifier = new QSocketNotifier(qintptr(s_pipe[0]), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &HangupWatcher::onReadable);
}

HangupWatcher::~HangupWatcher()
{
    if (s_pipe[0] < 0)
        return;
    delete m_notifier;
    sigaction(SIGHUP, &s_old, nullptr);
    ::close(s_pipe[0]);
    ::close(s_pipe[1]);
    s_pipe[0] = s_pipe[1] = -1;
}

void HangupWatcher::onReadable()
{
    char bytes[16];
    bool any = false;
    while (::read(s_pipe[0], bytes, sizeof bytes) > 0)
        any = true;
    // Several SIGHUPs in a row are one reload.
    if (any)
        Q_EMIT hangup();
}

#else

HangupWatcher::HangupWatcher(QObject *parent) : QObject(parent) {}
HangupWatcher::~HangupWatcher() = default;
void HangupWatcher::onReadable() {}

#endif

} // namespace mbscope::app
