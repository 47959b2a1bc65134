#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

#include <functional>

namespace mbscope {

class ConformanceContext;

// How much a check weighs in the scorecard: a mandatory check's failure fails the device (exit
// status 1); a recommended one is reported as a deviation without failing it; an informational
// one only measures (response times, the diagnostics sub-functions offered).
enum class CheckLevel : quint8 {
    Mandatory,
    Recommended,
    Informational,
};

enum class CheckVerdict : quint8 {
    Passed,
    Failed,  // the device did what the clause forbids: the sentence says what was sent, what came, what is required
    Skipped, // not run: the device does not claim what it needs (a function, a writable address, a framing); the sentence says why
    Error,   // could not be run: the link failed under it
};

[[nodiscard]] const char *checkLevelName(CheckLevel level);       // "mandatory", "recommended", "informational"
[[nodiscard]] const char *checkVerdictName(CheckVerdict verdict); // "passed", "failed", "skipped", "error"

// What a check needs of the device and the link before it runs; it is skipped, with the reason,
// when one is missing.
struct CheckNeeds {
    quint8 function = 0;     // a function code the device must support (0: none)
    bool mbap = false;       // a framing with an MBAP header (tcp, udp, tls)
    bool serial = false;     // a serial framing (rtu, ascii; also over TCP or UDP)
    bool stream = false;     // a connection (tcp, tls, rtu-tcp, ascii-tcp): several, closed, reopened
    bool serialPort = false; // RTU on a serial port (rtu://): the line's timing
    int readable = -1;       // a table (SimTable) with a readable address known; -1: none
    int writable = -1;       // a table (SimTable) with a writable address the user named; -1: none
};

// The outcome of one check, with the exchange it is judged on.
struct CheckResult {
    QString id;
    QString title;
    QString clause;
    CheckLevel level = CheckLevel::Mandatory;
    CheckVerdict verdict = CheckVerdict::Passed;
    QString sentence;    // failed: what was sent, what came back, what the clause requires; skipped: why; passed: what held
    QByteArray request;  // the request the verdict is about (the last one when there were several)
    QByteArray answer;   // every byte that came back for it (empty: silence)
    QString measured;    // figures an informational check reports ("median 4.1 ms, p95 5.0 ms")
    qint64 elapsedNs = 0;

    void pass(const QString &what) { verdict = CheckVerdict::Passed; sentence = what; }
    void fail(const QString &why) { verdict = CheckVerdict::Failed; sentence = why; }
    void skip(const QString &why) { verdict = CheckVerdict::Skipped; sentence = why; }
};

// One check of the battery: an id ("read.03.quantity-zero"), what it checks, the clause it cites,
// what it needs, and the code that exchanges and judges.
struct ConformanceCheck {
    QString id;
    QString title;
    QString clause;
    CheckLevel level = CheckLevel::Mandatory;
    CheckNeeds needs;
    std::function<void(ConformanceContext &context, CheckResult &result)> run;
};

} // namespace mbscope
