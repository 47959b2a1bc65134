#pragma once

#include "conformancecheck.h"
#include "conformancecontext.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QString>

namespace mbscope {

struct JUnitTestSuite;

// A scorecard: every check's result, what the survey learnt, and how the run ended.
struct ConformanceResult {
    QString target;
    quint8 unit = 1;
    QDateTime started;
    qint64 elapsedNs = 0;
    QList<CheckResult> checks;
    QMap<quint8, SurveyedSupport> support;
    bool linkFailed = false;  // the target could not be reached, or answered nothing at all
    QString linkMessage;
    bool interrupted = false;
    // The run was cut short: the device could no longer be reached during this check (an error);
    // the checks after it were not judged (skipped, saying so).
    QString linkLostAt;
    QString linkLostMessage;

    [[nodiscard]] int count(CheckVerdict verdict) const;
    [[nodiscard]] int failed(CheckLevel level) const;
    // The checks after linkLostAt (not judged).
    [[nodiscard]] int notJudged() const;
    // Every mandatory check passed or was skipped, and the run went through.
    [[nodiscard]] bool passed() const { return !linkFailed && !interrupted && linkLostAt.isEmpty() && failed(CheckLevel::Mandatory) == 0 && count(CheckVerdict::Error) == 0; }

    // "every mandatory check passed", "3 mandatory check(s) failed", "not tested: ...", "interrupted",
    // "cut short: the link was lost at check X (...): N check(s) after it not judged"
    [[nodiscard]] QString verdictSentence() const;
    // "67 checks: 60 passed, 1 failed (1 mandatory, 0 recommended), 6 skipped, 0 errors"
    [[nodiscard]] QString countsSentence() const;
    // "01 supported, 02 supported, 07 unsupported..."
    [[nodiscard]] QString supportSentence() const;
    // The verdict as the text report and the window show it: "PASS", "INFO" (an informational
    // check that measured), "FAIL" (mandatory), "WARN" (a recommended check failed), "SKIP", "ERROR".
    [[nodiscard]] static const char *label(const CheckResult &check);

    // The readable report: a line per check, the failures' sentences, the summary.
    [[nodiscard]] QString toText() const;
    // {"target", "unit", "started", "elapsed_ms", "passed", "counts": {...}, "functions": {"03": "supported"...},
    //  "checks": [{"id", "title", "clause", "level", "verdict", "sentence", "request", "answer", "measured", "elapsed_ms"}],
    //  "link_error" (when the link failed), "link_lost": {"check", "problem", "not_judged"} (when the run was cut short)}
    [[nodiscard]] QJsonObject toJson() const;
    // One test case per check, for JUnitReport.
    [[nodiscard]] JUnitTestSuite toJUnit() const;
    // "supported", "unsupported", "silent", "unknown", "not surveyed"
    [[nodiscard]] static const char *supportName(SurveyedSupport support);
};

} // namespace mbscope
