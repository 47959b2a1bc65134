#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace mbscope::app {

// The process signals a command answers, as Qt signals, read from a pipe by the event loop (the
// handler only writes the signal's number to it, the one thing a signal handler may safely do):
// - Ctrl-C (SIGINT) and SIGTERM: interrupted(), once, so a poll can stop and still print its
//   statistics. A second Ctrl-C ends the process at once, as users expect when the first one
//   seems not to work; one that comes within 300 ms of the first is the same one delivered twice
//   (timeout -s INT and scripts signal the command and then its process group) and is ignored.
// - SIGHUP, when watchHangup() asked for it (systemctl reload, kill -HUP): hangup(), every time
//   (several in a row are one), the handler staying since a service is reloaded many times.
// One watcher at a time; the handlers are restored when it goes.
class InterruptWatcher : public QObject
{
    Q_OBJECT
public:
    explicit InterruptWatcher(QObject *parent = nullptr);
    ~InterruptWatcher() override;

    // SIGHUP too, from now on (else it ends the process, its default).
    void watchHangup();

    [[nodiscard]] bool isInterrupted() const { return m_interrupted; }
    // The signal that interrupted (SIGINT or SIGTERM), 0 before one did.
    [[nodiscard]] int signalNumber() const { return m_signal; }

Q_SIGNALS:
    void interrupted();
    void hangup();

private:
    void onReadable();

    QSocketNotifier *m_notifier = nullptr;
    bool m_interrupted = false;
    bool m_hangup = false;
    int m_signal = 0;
};

} // namespace mbscope::app
