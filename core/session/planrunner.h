#pragma once

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"
#include "session/planresult.h"
#include "session/sessiondocument.h"
#include "transport/linkurl.h"

#include <functional>
#include <memory>
#include <optional>

class QEventLoop;

namespace mbscope {

class TrafficLog;
class TransactionEngine;
struct RequestItem;

// Runs a session's test plan against a target through a TransactionEngine and reports each step
// as it ends. Blocking: it runs local event loops while it waits (for answers, polls, waits), so
// it is called from a thread with an event loop (the main thread of `mbscope run`, or a test).
// A link error (nothing reaches the device) ends the run: the steps left are reported skipped.
class PlanRunner
{
public:
    using StepObserver = std::function<void(const StepResult &result)>;

    // url: where to run (the document's target or --target); target: the engine's settings
    // (timeout, retries, pipeline) from the document.
    PlanRunner(const SessionDocument &document, const LinkUrl &url, const SessionTarget &target);
    ~PlanRunner();
    PlanRunner(const PlanRunner &) = delete;
    PlanRunner &operator=(const PlanRunner &) = delete;

    // Every frame in and out goes to log (--record) until setTrafficLog(nullptr), which also
    // writes the engine's last frames to the log's journal (TransactionEngine::setTrafficLog).
    void setTrafficLog(TrafficLog *log);
    // Every frame in and out, as the engine logs it (TransactionEngine::framesLogged), handed to
    // observer in batches in the runner's thread while the plan runs; the last batch before run()
    // returns. For a window's traffic list.
    using FramesObserver = std::function<void(const QList<TrafficFrame> &frames, const QString &link)>;
    void setFramesObserver(FramesObserver observer);
    [[nodiscard]] PlanResult run(const StepObserver &observer = {});
    // Ends the run early (Ctrl-C): a poll in progress stops, a wait ends, a send finishes; the
    // steps left are reported skipped and the result says it was interrupted. Call it from the
    // runner's thread (an event the local loops deliver).
    void stop();

private:
    void runSteps(const std::vector<PlanStep> &steps, const QString &path, const QString &suffix);
    void runStep(const PlanStep &step, const QString &path, const QString &suffix);
    void runSend(const PlanStep &step, StepResult &result);
    void runExpect(const PlanStep &step, StepResult &result);
    void runPoll(const PlanStep &step, StepResult &result);
    void skip(const std::vector<PlanStep> &steps, std::size_t from, const QString &path, const QString &suffix);
    void skipStep(const PlanStep &step, const QString &path, const QString &suffix, int fromRepetition);
    [[nodiscard]] bool ended() const { return m_result.linkFailed || m_result.interrupted; }
    void report(const StepResult &result);
    [[nodiscard]] std::optional<RequestItem> item(const SessionRequest &request, QString *error);
    void check(const StepExpectation &expectation, const Transaction &transaction, StepResult &result) const;

    const SessionDocument &m_document;
    LinkUrl m_url;
    SessionTarget m_target;
    std::unique_ptr<TransactionEngine> m_engine;
    std::optional<Transaction> m_last; // the answer of the last send, for expect steps
    StepObserver m_observer;
    bool m_framesObserved = false;
    PlanResult m_result;
    quint16 m_transactionId = 1;
    QEventLoop *m_waitLoop = nullptr; // the wait step's, while one runs
    bool m_stopRequested = false;     // stop() before run(): every step is reported skipped
};

} // namespace mbscope
