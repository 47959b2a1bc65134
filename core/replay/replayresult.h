#pragma once

#include "exchange/statistics.h"
#include "replay/recordedwrite.h"
#include "replay/replayoutcome.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

class ReplayScript;

// What a replay against a live target found: every outcome, the counts by verdict, and the
// latency figures recorded and now (Statistics over the recorded and the replayed transactions).
struct ReplayResult {
    QString target;
    QList<ReplayOutcome> outcomes;
    // Recorded writes not sent (ReplayRunner::setSendWrites): neither matched nor differed.
    QList<RecordedWrite> skippedWrites;
    Statistics recorded;
    Statistics replayed;
    QStringList ignoredSelectors; // --ignore, as given: each is reported with how often it hid a difference
    bool interrupted = false;
    qint64 elapsedNs = 0;

    [[nodiscard]] qsizetype count(AnswerComparison::Verdict verdict) const;
    [[nodiscard]] qsizetype differed() const { return outcomes.size() - count(AnswerComparison::Verdict::Match); }
    [[nodiscard]] bool allMatched() const { return !interrupted && differed() == 0; }
    // Per --ignore selector: the answers in which it covered a difference, and the first such.
    struct IgnoredCount {
        QString selector;
        qsizetype answers = 0;
        QString first; // "modbus.register_value@0x007D: recorded 250, now 251" (request #N)
    };
    [[nodiscard]] QList<IgnoredCount> ignoredCounts() const;

    // "latency ms    recorded median 4.012  p95 7.901   now median 0.310  p95 0.522   (median -92.3 %)"
    [[nodiscard]] QString latencyLine() const;
    // The differences (each with its request number and the request's unit and function), the
    // writes not sent (each with its unit, function, address and quantity), then the counts and
    // the latency line; at most maxListed outcomes (and maxListed writes) are listed in full.
    [[nodiscard]] QString summary(const ReplayScript &script, int maxListed = 50) const;
    // {"target","replayed","matched","values_differ","outcome_differs","missing_answers",
    //  "skipped_writes","interrupted","elapsed_ms","differences":[{"request","sent","function","verdict","differences":[...],
    //  "ignored":[...]}], "skipped":[{"request","unit","function","name","address","quantity"}], "ignored":[{"field","answers","first"}],
    //  "latency_us":{"recorded":{median,p95,...},"replayed":{...}}}
    [[nodiscard]] QJsonObject toJson(const ReplayScript &script) const;
};

} // namespace mbscope
