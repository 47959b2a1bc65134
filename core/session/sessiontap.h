#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// The window's inline tap as a session keeps it (the connection bar's Tap row, saved when Tap is
// ticked): where masters connect and how requests are forwarded, in the words of `mbscope tap`'s
// options. The session's target is the tap's target for every unit the routes leave, and its
// timeout the forwarded requests' timeout. The URLs and routes are checked when the tap starts
// (the Tap row names what is wrong), as typed ones are.
struct SessionTap {
    QStringList listen;                         // --listen URLs
    QStringList routes;                         // --route UNITS[:DEVICE_UNIT]=URL
    bool readOnly = false;                      // --read-only
    QString refuse = QStringLiteral("exception"); // --refuse: exception or silence
    QString noAnswer = QStringLiteral("auto");  // --no-answer: auto, exception or silence
    int retries = 0;                            // --retries (0-100)

    friend bool operator==(const SessionTap &, const SessionTap &) = default;
};

} // namespace mbscope
