#include "interruptwatcher.h"

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
struct sigaction s_oldInt;
struct sigaction s_oldTerm;

void onSignal(int number)
{
    const int saved = errno;
    const char byte = char(number);
    // Nothing to do when the pipe is full: one byte already says "stop".
    [[maybe_unused]] const ssize_t n = ::write(s_pipe[1], &byte, 1);
    errno = saved;
}

} // namespace

InterruptWatcher::InterruptWatcher(QObject *parent)
    : QObject(parent)
{
    if (::pipe2(s_pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
        s_pipe[0] = s_pipe[1] = -1;
        return; // Ctrl-C then ends the process as usual; nothing worse
    }
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: the default action is back once the handler has run, for a second Ctrl-C.
    action.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGINT, &action, &s_oldInt);
    sigaction(SIGTERM, &action, &s_oldTerm);
    m_notifier = new QSocketNotifier(qintptr(s_pipe[0]), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &InterruptWatcher::onReadable);
}

InterruptWatcher::~InterruptWatcher()
{
    if (s_pipe[0] < 0)
        return;
    delete m_notifier;
    sigaction(SIGINT, &s_oldInt, nullptr);
    sigaction(SIGTERM, &s_oldTerm, nullptr);
    ::close(s_pipe[0]);
    ::close(s_pipe[1]);
    s_pipe[0] = s_pipe[1] = -1;
}

void InterruptWatcher::onReadable()
{
    char bytes[16];
    ssize_t n = 0;
    while ((n = ::read(s_pipe[0], bytes, sizeof bytes)) > 0) {
        if (m_signal == 0)
            m_signal = int(quint8(bytes[0]));
    }
    if (m_interrupted)
        return;
    m_interrupted = true;
    Q_EMIT interrupted();
}

#else

InterruptWatcher::InterruptWatcher(QObject *parent) : QObject(parent) {}
InterruptWatcher::~InterruptWatcher() = default;
void InterruptWatcher::onReadable() {}

#endif

} // namespace mbscope::app
