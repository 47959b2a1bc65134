#pragma once

#include "session/planstep.h"
#include "session/sessioncapture.h"
#include "session/sessionpoll.h"
#include "session/sessionprofile.h"
#include "session/sessionrequest.h"
#include "session/sessiontap.h"
#include "session/sessiontarget.h"
#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>
#include <vector>

namespace mbscope {

// A lab's work with a device, as one versioned JSON document (*.mbscope.json, format
// "mbscope-session"; docs/session.schema.json): the target, the requests built, the poll and
// sweep settings, the device profile, a reference to the captured traffic, a test plan and
// (since version 2) the watches and (since version 3) the window's inline tap.
// SessionReader reads it (every problem, with where it is), SessionWriter writes it atomically.
struct SessionDocument {
    // The newest version this mbscope writes; it reads this version and older. 2: the watches
    // (issue 16); 3: the tap (issue 27). A document is written with the lowest version that holds
    // what it has (versionNeeded()), so one without a tap still opens in an mbscope of version 2.
    static constexpr int kVersion = 3;
    static constexpr const char *kFormat = "mbscope-session";

    QString name;
    QString notes;
    SessionTarget target;
    QList<SessionRequest> requests;
    std::optional<SessionPoll> poll;
    std::optional<SessionSweep> sweep;
    SessionProfile profile;
    std::optional<SessionCapture> capture;
    std::vector<PlanStep> plan;
    SessionWatches watches;
    std::optional<SessionTap> tap; // the connection bar's Tap was ticked

    [[nodiscard]] int versionNeeded() const { return tap ? 3 : 2; }

    // The request of the given name, or nullptr.
    [[nodiscard]] const SessionRequest *request(const QString &requestName) const
    {
        for (const SessionRequest &r : requests) {
            if (r.name == requestName)
                return &r;
        }
        return nullptr;
    }

    friend bool operator==(const SessionDocument &, const SessionDocument &) = default;
};

} // namespace mbscope
