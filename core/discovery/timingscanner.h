#pragma once

#include "probechannel.h"
#include "scanprogress.h"

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>

#include <optional>

namespace mbscope {

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

    [[nodiscard]] QString problem() const;
};

// What a timing scan measured, and the settings it recommends.
struct TimingReport {
    qint64 firstAnswerMs = -1;   // from the first request on a new connection to its first good answer
    int warmupFailures = 0;      // requests that failed before it
    struct GapTrial {
        int gapMs = 0;
        int ok = 0;
        int failed = 0;
        qint64 maxLatencyUs = 0;
    };
    QList<GapTrial> gaps;        // longest first, until errors started
    int shortestCleanGapMs = -1; // -1: every gap tried had errors
    qint64 maxLatencyUs = 0;     // over every good answer
    int pipelineSent = 0;        // 0: not tried (not MBAP)
    int pipelineOk = 0;
    int clientsTried = 0;        // 0: not tried (not a TCP link)
    int clientsServed = 0;       // connections answered while all of them stayed open
    bool oldestDropped = false;  // client clientsTried was served by closing the oldest (dropOldest)
    int largestQuantity = 0;     // the largest read quantity answered at address
    int largestAnswerPdu = 0;    // its answer's PDU size in bytes

    [[nodiscard]] int recommendedGapMs() const;
    [[nodiscard]] int recommendedTimeoutMs() const;
};

// A device's timing limits through a link (issue 18, item 4): how long after connecting it
// answers, the shortest gap between requests before errors start, whether pipelined MBAP requests
// are answered, how many TCP clients it serves at once, and the largest read it answers. Reads only.
class TimingScanner : public QObject
{
    Q_OBJECT
public:
    explicit TimingScanner(QObject *parent = nullptr);

    [[nodiscard]] std::optional<TimingReport> run(const TimingScanSettings &settings);
    void stop()
    {
        m_stopRequested = true;
        m_channel->cancel();
    }
    [[nodiscard]] bool wasStopped() const { return m_stopRequested; }

Q_SIGNALS:
    void step(const QString &what);

private:
    void warmup(TimingReport &report);
    void gaps(TimingReport &report);
    void pipelining(TimingReport &report);
    void clients(TimingReport &report);
    void largestRead(TimingReport &report);
    [[nodiscard]] QByteArray readPdu(int quantity) const;
    // How long a new connection waits before its first request: the warm-up seen, and the gap.
    [[nodiscard]] qint64 settleMs(const TimingReport &report) const;

    ProbeChannel *m_channel;
    TimingScanSettings m_settings;
    bool m_stopRequested = false;
};

} // namespace mbscope
