#pragma once

#include <QtCore/QEvent>
#include <QtCore/QSocketNotifier>

namespace mbscope {

// A socket notifier whose owner handles activation itself (activate()), instead of through the
// activated() signals. The engine's dispatcher (EngineEventDispatcher) calls activate() directly,
// without QCoreApplication::sendEvent() and its notify() and event-filter steps (about 350
// instructions per read, issue 3); any other dispatcher sends the QEvent::SockAct event as usual,
// which reaches the same activate().
class DirectSocketNotifier : public QSocketNotifier
{
public:
    DirectSocketNotifier(Type type, QObject *parent)
        : QSocketNotifier(type, parent)
    {
    }

    // The descriptor is ready (as activated() would say). Called in the notifier's thread.
    virtual void activate() = 0;

protected:
    bool event(QEvent *e) override
    {
        if (e->type() == QEvent::SockAct) {
            activate();
            return true;
        }
        return QSocketNotifier::event(e);
    }
};

} // namespace mbscope
