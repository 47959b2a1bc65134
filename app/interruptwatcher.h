#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace mbscope::app {

// Ctrl-C (SIGINT) and SIGTERM as a Qt signal, so a poll can stop and still print its statistics.
// The handler only writes a byte to a pipe (the one thing a signal handler may safely do) and
// puts the default action back: a second Ctrl-C ends the process at once, as users expect when
// the first one seems not to work. The event loop reads the pipe and emits interrupted().
// One watcher at a time; the handlers are restored when it goes.
class InterruptWatcher : public QObject
{
    Q_OBJECT
public:
    explicit InterruptWatcher(QObject *parent = nullptr);
    ~InterruptWatcher() override;

    [[nodiscard]] bool isInterrupted() const { return m_interrupted; }
    // The signal that arrived (SIGINT or SIGTERM), 0 before one did.
    [[nodiscard]] int signalNumber() const { return m_signal; }

Q_SIGNALS:
    void interrupted();

private:
    void onReadable();

    QSocketNotifier *m_notifier = nullptr;
    bool m_interrupted = false;
    int m_signal = 0;
};

} // namespace mbscope::app
