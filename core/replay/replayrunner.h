#pragma once

#include "engine/engineoptions.h"
#include "replay/ignoredfields.h"
#include "replay/replayresult.h"
#include "transport/linkurl.h"

#include <QtCore/QByteArray>

#include <functional>
#include <memory>

class QEventLoop;

namespace mbscope {

class ReplayScript;
class TrafficLog;
class TransactionEngine;

// Re-sends a ReplayScript's requests to a live target through the TransactionEngine, one at a
// time, at the recorded pacing (each request at its recorded offset from the first, divided by
// the speed factor; speed 0 sends back to back), and compares each answer with the recorded
// one (AnswerComparison). A request whose answer takes longer than the recorded interval delays
// the ones after it: replay never sends two requests at once, as the recording did not.
//
// Requests recorded in the target's framing are sent byte for byte; in another framing they are
// re-framed from their unit and PDU (MBAP transaction ids 1, 2, 3...).
//
// Recorded writes (RecordedWrite: 05, 06, 0F, 10, 15, 16, 17) are not sent unless
// setSendWrites(true): a replay to a real device would move its outputs. Each one skipped is in
// ReplayResult::skippedWrites, and is not waited for.
// Runs a local event loop: call from a thread with none running (the CLI's main thread).
class ReplayRunner
{
public:
    using Observer = std::function<void(const ReplayOutcome &outcome)>;

    ReplayRunner(const ReplayScript &script, const LinkUrl &target, const EngineOptions &options = {},
                 int timeoutMs = -1);
    ~ReplayRunner();
    ReplayRunner(const ReplayRunner &) = delete;
    ReplayRunner &operator=(const ReplayRunner &) = delete;

    // 1: recorded pacing; 10: ten times faster; 0: no waiting at all.
    void setSpeed(double speed) { m_speed = speed; }
    // Whether recorded writes are sent (false by default: they are skipped and listed).
    void setSendWrites(bool send) { m_sendWrites = send; }
    // Fields expected to change (--ignore): their differences are reported as ignored.
    void setIgnoredFields(const IgnoredFields &ignore) { m_ignore = ignore; }
    // Every frame in and out goes to log (--record) until setTrafficLog(nullptr), which also
    // writes the engine's last frames to the log's journal (TransactionEngine::setTrafficLog).
    void setTrafficLog(TrafficLog *log);
    // The engine that sends: its frames as it logs them (TransactionEngine::framesLogged), for a
    // live frame log.
    [[nodiscard]] TransactionEngine *engine() const { return m_engine.get(); }
    [[nodiscard]] ReplayResult run(const Observer &observer = {});
    // From a Ctrl-C handler's event: stops after the request in flight.
    void stop();

    // The bytes that carry exchange index of the script on a link with the given framing.
    [[nodiscard]] static QByteArray wireBytes(const ReplayScript &script, qsizetype index, Framing framing);

private:
    void waitUntil(qint64 dueNs);

    const ReplayScript &m_script;
    LinkUrl m_target;
    int m_timeoutMs;
    double m_speed = 1.0;
    IgnoredFields m_ignore;
    bool m_sendWrites = false;
    bool m_stopped = false;
    QEventLoop *m_waitLoop = nullptr;
    std::unique_ptr<TransactionEngine> m_engine;
};

} // namespace mbscope
