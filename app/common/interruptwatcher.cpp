#include "common/interruptwatcher.h"

#include <QtCore/QSocketNotifier>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#endif

namespace mbscope::app {

#ifdef Q_OS_UNIX

namespace {

int s_pipe[2] = {-1, -1};
struct sigaction s_oldInt;
struct sigaction s_oldTerm;
struct sigaction s_oldHup;
// The first Ctrl-C or SIGTERM and when it came (CLOCK_MONOTONIC).
volatile sig_atomic_t s_interrupted = 0;
struct timespec s_firstAt = {};

// A second interrupt this soon after the first is the same one delivered twice: timeout(1) and
// scripts signal the command and then its whole process group, microseconds apart. A person's
// second Ctrl-C comes later.
constexpr long long kSameInterruptMs = 300;

void onSignal(int number)
{
    const int saved = errno;
    if (number != SIGHUP) {
        struct timespec now = {};
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (s_interrupted) {
            const long long ms = (now.tv_sec - s_firstAt.tv_sec) * 1000LL + (now.tv_nsec - s_firstAt.tv_nsec) / 1000000LL;
            if (ms < kSameInterruptMs) {
                errno = saved;
                return;
            }
            // A second Ctrl-C: the default action, at once (both calls are async-signal-safe).
            signal(number, SIG_DFL);
            raise(number);
            errno = saved;
            return;
        }
        if (s_pipe[1] < 0) { // no watcher any more: the default action
            signal(number, SIG_DFL);
            raise(number);
            errno = saved;
            return;
        }
        s_firstAt = now;
        s_interrupted = 1;
    }
    const char byte = char(number);
    // Nothing to do when the pipe is full: the bytes already there say it.
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
    s_interrupted = 0;
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    // The handler itself puts the default action back for a second Ctrl-C (not one delivered twice).
    action.sa_flags = SA_RESTART;
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
    // After an interrupt the handler stays: the same one delivered again in the next moments (the
    // command's exit is quick) must not kill the process while it prints; a later one ends it
    // at once, as the default would.
    if (!s_interrupted) {
        sigaction(SIGINT, &s_oldInt, nullptr);
        sigaction(SIGTERM, &s_oldTerm, nullptr);
    }
    if (m_hangup)
        sigaction(SIGHUP, &s_oldHup, nullptr);
    ::close(s_pipe[0]);
    ::close(s_pipe[1]);
    s_pipe[0] = s_pipe[1] = -1;
}

void InterruptWatcher::watchHangup()
{
    if (s_pipe[0] < 0 || m_hangup)
        return;
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART; // stays: a service is reloaded many times
    sigaction(SIGHUP, &action, &s_oldHup);
    m_hangup = true;
}

void InterruptWatcher::onReadable()
{
    char bytes[16];
    ssize_t n = 0;
    bool sawInterrupt = false;
    bool sawHangup = false;
    while ((n = ::read(s_pipe[0], bytes, sizeof bytes)) > 0) {
        for (ssize_t i = 0; i < n; ++i) {
            const int number = int(quint8(bytes[i]));
            if (number == SIGHUP) {
                sawHangup = true;
            } else {
                sawInterrupt = true;
                if (m_signal == 0)
                    m_signal = number;
            }
        }
    }
    if (sawHangup && !m_interrupted)
        Q_EMIT hangup();
    if (sawInterrupt && !m_interrupted) {
        m_interrupted = true;
        Q_EMIT interrupted();
    }
}

#else

InterruptWatcher::InterruptWatcher(QObject *parent) : QObject(parent) {}
InterruptWatcher::~InterruptWatcher() = default;
void InterruptWatcher::watchHangup() {}
void InterruptWatcher::onReadable() {}

#endif

} // namespace mbscope::app
