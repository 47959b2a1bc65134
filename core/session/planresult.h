#pragma once

#include "session/planstep.h"

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// What one step of a plan did (a repeated step gives one result per repetition).
struct StepResult {
    enum class Outcome : quint8 {
        Passed,
        Failed,  // an expectation did not hold: reasons say which and what was seen
        Error,   // the step could not run: the link failed, or a request could not be made
        Skipped, // not run: an earlier step's link error stopped the plan
    };
    QString path;        // "plan[2]", "plan[4].steps[1]"
    QString name;        // the step's name, "(2/3)" added in a repeat
    PlanStep::Kind kind = PlanStep::Kind::Send;
    Outcome outcome = Outcome::Passed;
    QStringList reasons; // why it failed, or what was checked when it passed
    QString detail;      // what was exchanged: "sent 01 03 ..., answer 01 03 2C ... in 4.213 ms"
    qint64 elapsedNs = 0;

    [[nodiscard]] static const char *outcomeName(Outcome outcome); // "passed", "failed", "error", "skipped"
};

struct PlanResult {
    QString name;   // the document's name (or its file name)
    QString target; // the URL run against
    QDateTime started;
    qint64 elapsedNs = 0;
    QList<StepResult> steps;
    bool linkFailed = false;
    QString linkMessage;
    bool interrupted = false; // stopped early (Ctrl-C): the steps left are skipped

    [[nodiscard]] int count(StepResult::Outcome outcome) const;
    [[nodiscard]] bool passed() const { return !linkFailed && !interrupted && count(StepResult::Outcome::Passed) == steps.size(); }
    // {"plan", "target", "started", "elapsed_ms", "passed", "counts": {...}, "steps": [{"path",
    //  "name", "kind", "outcome", "reasons", "detail", "elapsed_ms"}], "link_error", "interrupted"}
    [[nodiscard]] QJsonObject toJson() const;
};

[[nodiscard]] QString planStepKindName(PlanStep::Kind kind); // "send", "expect", "poll", "wait", "repeat"

} // namespace mbscope
