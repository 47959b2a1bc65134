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
    // The runs this result stands for: 1, except for the skipped rest of a repeat too long to
    // list run by run (more than PlanResult::kListedSkips), reported as one result.
    int runs = 1;

    [[nodiscard]] static const char *outcomeName(Outcome outcome); // "passed", "failed", "error", "skipped"
};

struct PlanResult {
    QString name;   // the document's name (or its file name)
    QString target; // the URL run against
    QDateTime started;
    qint64 elapsedNs = 0;
    int planned = 0;          // planStepCount(plan): steps.size() once the run ends, however it ends
    QList<StepResult> steps;
    bool linkFailed = false;
    QString linkMessage;
    bool interrupted = false; // stopped early (Ctrl-C): the steps left are skipped

    // Skipped runs of a repeat are listed one by one up to this many; beyond, one result says how many.
    static constexpr int kListedSkips = 10000;

    // Runs with this outcome, and all runs (each result counted for its runs): the count the
    // window, the CLI and JUnit show, planned however the run ended.
    [[nodiscard]] int count(StepResult::Outcome outcome) const;
    [[nodiscard]] int total() const;
    [[nodiscard]] bool passed() const { return !linkFailed && !interrupted && count(StepResult::Outcome::Passed) == total(); }
    // {"plan", "target", "started", "elapsed_ms", "passed", "total", "counts": {...}, "steps": [{"path",
    //  "name", "kind", "outcome", "reasons", "detail", "elapsed_ms", "runs" (when more than 1)}],
    //  "link_error", "interrupted"}
    [[nodiscard]] QJsonObject toJson() const;
};

// The steps a plan runs, each repetition of a repeat's steps counted: what a run reports, one
// result each (passed, failed, error or skipped), in the window, the CLI and JUnit alike.
[[nodiscard]] int planStepCount(const std::vector<PlanStep> &steps);

[[nodiscard]] QString planStepKindName(PlanStep::Kind kind); // "send", "expect", "poll", "wait", "repeat"

} // namespace mbscope
