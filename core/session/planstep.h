#pragma once

#include "session/pollbound.h"
#include "session/sessionpoll.h"
#include "session/sessionrequest.h"
#include "session/stepexpectation.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>
#include <vector>

namespace mbscope {

// One step of a test plan. A step does one thing:
//   Send    a request (one of the document's by name, or its own, hex or form), and checks the
//           answer when it has an expectation
//   Expect  checks the answer of the send before it again (another expectation, another name)
//   Poll    runs a poll and checks bounds on its statistics ("p95 < 20 ms", "timeouts == 0")
//   Wait    lets time pass (a device settling after a write)
//   Repeat  runs its steps a number of times
struct PlanStep {
    enum class Kind : quint8 { Send, Expect, Poll, Wait, Repeat };

    Kind kind = Kind::Send;
    QString name;
    QString notes;

    // Send: requestName names one of the document's requests; otherwise request is the step's own.
    QString requestName;
    SessionRequest request;
    // Send and Expect.
    StepExpectation expect;
    // Poll.
    SessionPoll poll;
    QList<PollBound> bounds;
    // Wait.
    qint64 waitMs = 0;
    // Repeat.
    int times = 1;
    std::vector<PlanStep> steps;

    friend bool operator==(const PlanStep &, const PlanStep &) = default;
};

} // namespace mbscope
