#pragma once

#include "common/progressline.h"
#include "common/targetoptions.h"

#include "engine/engineoptions.h"
#include "engine/pollreport.h"
#include "engine/pollsettings.h"

#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {
class TrafficLog;
class TransactionEngine;
struct EngineProgress;
struct Transaction;
}

namespace mbscope::app {

class FrameLog;
class PollTranscript;

struct PollOutcome {
    PollReport report;
    bool interrupted = false; // Ctrl-C (or SIGTERM) stopped it
    bool linkFailed = false;  // the link never worked: the first records were link errors
    QString linkMessage;      // what the link said then
};

// Runs a poll or a sweep for poll and sweep: the engine on its thread, a live progress line on a
// terminal, Ctrl-C to stop (the statistics so far still come back), and a quick end when the
// link cannot be opened at all (a refused port should not take a 60 s poll to say so). A link
// that worked and then failed is not stopped: its link errors are part of the statistics.
class PollRunner : public QObject
{
    Q_OBJECT
public:
    PollRunner(const TargetSettings &target, const EngineOptions &options, QObject *parent = nullptr);
    ~PollRunner() override;

    // Every frame goes to log (--record), from the start of run() until it returns; every
    // transaction to the transcript (--print values, --csv) as its batch arrives.
    void setTrafficLog(TrafficLog *log) { m_log = log; }
    void setTranscript(PollTranscript *transcript) { m_transcript = transcript; }
    // Every frame to the frame log (--print frames, --frame-log) as its batch arrives.
    void setFrameLog(FrameLog *log) { m_frameLog = log; }

    // Blocks (running an event loop) until the poll or sweep ends.
    [[nodiscard]] PollOutcome run(const SweepSettings &settings, bool sweep);

private:
    void onProgress(const EngineProgress &progress);
    void onTransactions(const QList<Transaction> &transactions);

    TargetSettings m_target;
    TransactionEngine *m_engine;
    TrafficLog *m_log = nullptr;
    PollTranscript *m_transcript = nullptr;
    FrameLog *m_frameLog = nullptr;
    ProgressLine m_line;
    bool m_sweep = false;
    bool m_sawAnswer = false;
    bool m_linkFailed = false;
    bool m_interrupted = false;
    QString m_linkMessage;
    qint64 m_lastLatencyNs = -1;
};

} // namespace mbscope::app
