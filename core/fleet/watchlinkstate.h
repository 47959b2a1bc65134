#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// The health of one link the watches share.
struct WatchLinkState {
    enum class State : quint8 {
        Connecting, // opening (first time, or after a backoff)
        Up,         // open, answering or not
        Down,       // lost: the polls of its watches fail with link errors
        Backoff,    // waiting retryInMs before opening again
        Stopped,    // the runner stopped
    };

    QString target;           // the link URL as the watches give it
    State state = State::Connecting;
    QString message;          // what the link said when it failed
    int retryInMs = 0;        // Backoff: the wait before the next attempt
    quint64 reconnects = 0;   // times the link opened again after it was lost
    quint64 failures = 0;     // link errors (failed opens included)
    qint64 timeMs = 0;        // when the state was entered, ms since the epoch, UTC
};

[[nodiscard]] QString watchLinkStateName(WatchLinkState::State state); // "connecting", "up", "down"...

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::WatchLinkState)
