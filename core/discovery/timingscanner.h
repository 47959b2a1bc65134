#pragma once

#include "probechannel.h"
#include "job/jobend.h"
#include "job/jobprogress.h"

#include "transport/linkurl.h"

#include <QtCore/QJsonObject>
#include <QtCore/QElapsedTimer>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QObject>

#include <optional>

namespace mbscope {

class TrafficLog;
class TransactionEngine;

struct TimingScanSettings {
    LinkUrl url;
    quint8 unit = 1;
    quint8 function = 3;
    quint16 address = 0;
    int timeoutMs = 1000;
    QList<int> gapsMs{200, 100, 50, 20, 10, 5, 2, 1, 0}; // tried from the longest down
    int requestsPerGap = 20;
    int pipelineDepth = 8;  // MBAP links: requests sent without waiting
    int maxClients = 16;    // MBAP and other TCP links: connections held open at once
    int warmupLimitMs = 10000;
    qint64 maxDurationMs = 600000; // the whole scan: no request is sent that would end after it

    [[nodiscard]] QString problem() const;
};

// What a timing scan measured, and the settings it recommends.
struct TimingReport {
    qint64 firstAnswerMs = -1;   // from the first request on a new connection to its first good answer
    int warmupFailures = 0;      // requests that failed before it
    // With failures before the first answer, the warm-up found to 10 ms (waits on new
    // connections, halved in between): the shortest wait after a connection opened before a
    // request that was answered, and the longest that was not (-1: not measured).
    qint64 warmUpMs = -1;
    qint64 warmUpRefusedMs = -1;
    // What a client waits after connecting: warmUpMs (firstAnswerMs when it could not be
    // narrowed), 0 when the first request was answered.
    [[nodiscard]] qint64 pauseAfterConnectMs() const
    {
        return warmupFailures > 0 ? (warmUpMs >= 0 ? warmUpMs : firstAnswerMs) : 0;
    }
    struct GapTrial {
        int gapMs = 0;
        int ok = 0;
        int failed = 0;
        qint64 maxLatencyUs = 0;
    };
    QList<GapTrial> gaps;        // longest first, until errors started
    int shortestCleanGapMs = -1; // -1: every gap tried had errors
    // The device hangs up after each answer and each new connection waits its warm-up: gaps
    // shorter than the first tried could not be asked (not measured; no minGapMs from them).
    bool gapsHeldByWarmUp = false;
    qint64 maxLatencyUs = 0;     // over every good answer
    int pipelineSent = 0;        // 0: not tried (not MBAP)
    int pipelineOk = 0;
    int clientsTried = 0;        // 0: not tried (not a TCP link)
    int clientsServed = 0;       // connections answered while all of them stayed open
    bool oldestDropped = false;  // client clientsTried was served by closing the oldest (dropOldest)
    // Which parts ran to their end (not cut short by a stop or the time limit): what a part that
    // did not says is a lower bound at most, and nothing at all when it measured nothing.
    bool gapsComplete = false;
    bool largestComplete = false;
    int largestQuantity = 0;     // the largest read quantity answered at address
    int largestAnswerPdu = 0;    // its answer's PDU size in bytes
    bool largestFound = false;   // largestQuantity is the specification's, or one more was refused with 03 (not cut short)
    bool largestEndsMap = false; // one more was refused otherwise (02: the read ran past the map), not for its quantity
    // Stream links: the answers of the gap trials, and the connections the channel had to open
    // again for their requests (0 when the device keeps the connection; one an answer when it
    // hangs up after each).
    int gapAnswered = 0;
    int gapReconnects = -1;      // -1: not measured (serial lines, datagrams)

    // The device closed the connection after every answer of the gap trials (three at least;
    // the first request may have found the warm-up's connection still open; a request that
    // failed may or may not have needed one). Pipelining and clients at once cannot be measured
    // then: those parts are skipped.
    [[nodiscard]] bool closesAfterAnswer() const { return gapReconnects >= 0 && gapAnswered >= 3 && gapReconnects >= gapAnswered - 1; }

    // Whether a gap between requests was measured at all: a clean one, or every one tried failing
    // through to the end of the part.
    [[nodiscard]] bool gapMeasured() const { return gapsHeldByWarmUp || shortestCleanGapMs >= 0 || (gapsComplete && !gaps.isEmpty()); }
    [[nodiscard]] int recommendedGapMs() const;
    [[nodiscard]] int recommendedTimeoutMs() const;
    // What was measured as a profile's "limits" (docs/profiles.md, Device limits; what
    // DeviceLimitsReader reads), for ProfileDraft::mergeLimits: minGapMs the shortest clean gap
    // when a shorter one had errors (null when 0 ms was clean), warmUpMs the first answer's time
    // when requests failed before it (null when the first was answered), maxClients (and
    // extraClients) when a client beyond them was not served alongside, maxQuantity of function
    // the largest read (null when the specification's was answered), closesAfterAnswer (null when
    // the connection stayed open). What was not measured is left out; a null says the device
    // showed no such limit.
    [[nodiscard]] QJsonObject profileLimits(quint8 function) const;
    // The largest read answered (function -> largestQuantity; empty when none was), which
    // disproves a smaller maxQuantity a profile holds even when no limit was found.
    [[nodiscard]] QMap<int, int> answeredReads(quint8 function) const;
};

// A device's timing limits through a link (issue 18, item 4): how long after connecting it
// answers, the shortest gap between requests before errors start, whether pipelined MBAP requests
// are answered, how many TCP clients it serves at once, and the largest read it answers. Reads only.
// Bounded by the settings' counts and time limit. Its progress counts steps of a plan known at the
// start (the first answer, every request of every gap, the largest read's bisection, the pipelined
// burst, every client); a part that ends early (errors started, the bisection was short) counts
// its steps left as done, so done only grows and reaches total when the scan completes.
class TimingScanner : public QObject
{
    Q_OBJECT
public:
    explicit TimingScanner(QObject *parent = nullptr);

    // The report, or nullopt with settings.problem() unusable. end() says how it ended.
    [[nodiscard]] std::optional<TimingReport> run(const TimingScanSettings &settings);
    void stop();
    [[nodiscard]] JobEnd end() const { return m_end; }
    // Every frame of every connection the scan opens goes to log (ProbeChannel::setTrafficLog),
    // each connection on a link id of its own: the log must be shared (TrafficLog::setShared),
    // and outlive the scanner.
    void setTrafficLog(TrafficLog *log);
    // framesLogged() on or off (off by default), for the next run().
    void setFramesPublished(bool published) { m_framesPublished = published; }
    // The channel of its one-at-a-time requests (its frames: ProbeChannel::framesLogged).
    [[nodiscard]] ProbeChannel *channel() { return m_channel; }
    // Steps done of the plan, and the time left: the plan's waits (gaps, warm-up, settling) and
    // one answer a step, at the average answer time measured so far (the timeout before any).
    [[nodiscard]] JobProgress progress() const;

Q_SIGNALS:
    void step(const QString &what);
    void progressChanged(const mbscope::JobProgress &progress);
    // stop() was called: the waits of the part running end.
    void stopping();
    // With setFramesPublished(true): every frame of every connection as its engine logs it
    // (TransactionEngine::framesLogged: the probe channel's, the pipelined burst's, each client's),
    // link its URL.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

private:
    enum Part : quint8 { Warmup, Gaps, Largest, Pipeline, Clients, PartCount };
    void warmup(TimingReport &report);
    void narrowWarmUp(TimingReport &report, int timeoutMs);
    void gaps(TimingReport &report);
    void pipelining(TimingReport &report);
    void clients(TimingReport &report);
    void largestRead(TimingReport &report);
    [[nodiscard]] QByteArray readPdu(int quantity) const;
    // How long a new connection waits before its first request: the warm-up seen, and the gap.
    [[nodiscard]] qint64 settleMs(const TimingReport &report) const;
    // False (and end() set) when stopped, or when a step of nextMs would end after the time limit.
    [[nodiscard]] bool mayContinue(qint64 nextMs);
    // A request through the probe channel, its answer time kept for the estimate.
    [[nodiscard]] std::optional<ProbeChannel::Answer> ask(int quantity, int timeoutMs, bool measured = true);
    void beginPart(Part part, const QString &what);
    void stepDone();
    void endPart(Part part); // the part's steps left count as done
    [[nodiscard]] qint64 answerMs() const;
    // An engine of the burst or of a client: recorded to the log and its frames published, as the
    // channel's are.
    void observe(TransactionEngine &engine);
    [[nodiscard]] qint64 stepCostMs(int index) const;

    ProbeChannel *m_channel;
    TrafficLog *m_log = nullptr;
    bool m_framesPublished = false;
    TimingScanSettings m_settings;
    const TimingReport *m_report = nullptr; // while run() runs: the estimate reads the gaps and warm-up seen
    QElapsedTimer m_clock;
    bool m_stopRequested = false;
    JobEnd m_end = JobEnd::Completed;
    int m_opens = 0; // the channel's link openings
    int m_partStart[PartCount + 1] = {};
    int m_done = 0;
    qint64 m_answeredMs = 0; // time of the measured requests beyond their gaps
    int m_answered = 0;
};

} // namespace mbscope
