#pragma once

#include "session/planstep.h"
#include "session/sessioncapture.h"
#include "session/sessionpoll.h"
#include "session/sessionprofile.h"
#include "session/sessionrequest.h"
#include "session/sessiontarget.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>
#include <vector>

namespace mbscope {

// A lab's work with a device, as one versioned JSON document (*.mbscope.json, format
// "mbscope-session"; docs/session.schema.json): the target, the requests built, the poll and
// sweep settings, the device profile, a reference to the captured traffic and a test plan.
// SessionReader reads it (every problem, with where it is), SessionWriter writes it atomically.
struct SessionDocument {
    static constexpr int kVersion = 1;                 // what this mbscope writes and reads
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
