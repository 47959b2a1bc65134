#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace mbscope::app {

// SIGHUP as a Qt signal, every time it arrives (systemctl reload, kill -HUP): the watch service
// reads its session again. The handler writes a byte to a pipe, as InterruptWatcher's does; unlike
// it, the handler stays, since a service is reloaded many times. One watcher at a time.
class HangupWatcher : public QObject
{
    Q_OBJECT
public:
    explicit HangupWatcher(QObject *parent = nullptr);
    ~HangupWatcher() override;

Q_SIGNALS:
    void hangup();

private:
    void onReadable();

    QSocketNotifier *m_notifier = nullptr;
};

} // namespace mbscope::app
