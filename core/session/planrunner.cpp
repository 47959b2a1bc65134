#include "session/planrunner.h"

#include "exchange/requestitem.h"
#include "engine/transactionengine.h"
#include "protocol/hextext.h"
#include "session/expectationcheck.h"
#include "transport/monotonicclock.h"

#include <QtCore/QEventLoop>
#include <QtCore/QFileInfo>
#include <QtCore/QTimer>

namespace mbscope {

namespace {

QString msText(qint64 ns)
{
    return QString::number(double(ns) / 1e6, 'f', 3) + QStringLiteral(" ms");
}

QString exchangeText(const Transaction &t)
{
    QString text = QStringLiteral("sent %1").arg(HexText::format(t.request));
    if (!t.response.isEmpty())
        text += QStringLiteral(", answer %1 in %2").arg(HexText::format(t.response), msText(t.latencyNs()));
    else
        text += QStringLiteral(", %1").arg(ExpectationCheck::describeAnswer(t));
    return text;
}

} // namespace

PlanRunner::PlanRunner(const SessionDocument &document, const LinkUrl &url, const SessionTarget &target)
    : m_document(document), m_url(url), m_target(target), m_engine(std::make_unique<TransactionEngine>())
{
    EngineOptions options;
    options.pipelineDepth = target.pipelineDepth;
    m_engine->setTarget(url, options);
}

void PlanRunner::setTrafficLog(TrafficLog *log)
{
    m_engine->setTrafficLog(log);
}

void PlanRunner::setFramesObserver(FramesObserver observer)
{
    m_framesObserved = bool(observer);
    m_engine->setFramesPublished(m_framesObserved);
    QObject::disconnect(m_engine.get(), &TransactionEngine::framesLogged, nullptr, nullptr);
    if (m_framesObserved)
        QObject::connect(m_engine.get(), &TransactionEngine::framesLogged, m_engine.get(), std::move(observer));
}

PlanRunner::~PlanRunner() = default;

PlanResult PlanRunner::run(const StepObserver &observer)
{
    m_observer = observer;
    m_result = PlanResult{};
    m_result.name = m_document.name;
    m_result.target = m_url.toString();
    m_result.started = QDateTime::currentDateTimeUtc();
    m_result.planned = planStepCount(m_document.plan);
    m_result.interrupted = m_stopRequested;
    m_last.reset();
    const qint64 start = monotonicNowNs();
    runSteps(m_document.plan, QStringLiteral("plan"), QString());
    m_result.elapsedNs = monotonicNowNs() - start;
    m_engine->closeLink();
    if (m_framesObserved)
        m_engine->deliverPending();
    return m_result;
}

void PlanRunner::stop()
{
    m_stopRequested = true;
    m_result.interrupted = true;
    m_engine->stop();
    if (m_waitLoop)
        m_waitLoop->quit();
}

void PlanRunner::report(const StepResult &result)
{
    m_result.steps.append(result);
    if (m_observer)
        m_observer(result);
}

void PlanRunner::skip(const std::vector<PlanStep> &steps, std::size_t from, const QString &path, const QString &suffix)
{
    for (std::size_t i = from; i < steps.size(); ++i)
        skipStep(steps[i], QStringLiteral("%1[%2]").arg(path).arg(i), suffix, 1);
}

// Every run a full plan would have made is reported, a skipped one as skipped: the count of
// results is planStepCount(plan) however the run ends (the window, the CLI and JUnit agree).
void PlanRunner::skipStep(const PlanStep &step, const QString &path, const QString &suffix, int fromRepetition)
{
    if (step.kind == PlanStep::Kind::Repeat) {
        const qint64 left = qint64(step.times - fromRepetition + 1) * planStepCount(step.steps);
        if (left <= PlanResult::kListedSkips) {
            for (int n = fromRepetition; n <= step.times; ++n)
                skip(step.steps, 0, path + QStringLiteral(".steps"), suffix + QStringLiteral(" (%1/%2)").arg(n).arg(step.times));
            return;
        }
        // A repeat may run millions of times: its rest is one result that counts every run.
        StepResult r;
        r.path = path;
        r.name = step.name + suffix + QStringLiteral(" (%1/%2 to %2/%2)").arg(fromRepetition).arg(step.times);
        r.kind = step.kind;
        r.outcome = StepResult::Outcome::Skipped;
        r.runs = int(left);
        r.reasons.append((m_result.linkFailed ? QStringLiteral("not run: the link failed earlier")
                                              : QStringLiteral("not run: the run was interrupted"))
                         + QStringLiteral(" (%1 runs)").arg(left));
        report(r);
        return;
    }
    StepResult r;
    r.path = path;
    r.name = step.name + suffix;
    r.kind = step.kind;
    r.outcome = StepResult::Outcome::Skipped;
    r.reasons.append(m_result.linkFailed ? QStringLiteral("not run: the link failed earlier")
                                         : QStringLiteral("not run: the run was interrupted"));
    report(r);
}

void PlanRunner::runSteps(const std::vector<PlanStep> &steps, const QString &path, const QString &suffix)
{
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const QString at = QStringLiteral("%1[%2]").arg(path).arg(i);
        if (ended()) {
            skip(steps, i, path, suffix);
            return;
        }
        runStep(steps[i], at, suffix);
    }
}

void PlanRunner::runStep(const PlanStep &step, const QString &path, const QString &suffix)
{
    if (step.kind == PlanStep::Kind::Repeat) {
        for (int n = 1; n <= step.times; ++n) {
            if (ended()) {
                skipStep(step, path, suffix, n);
                break;
            }
            runSteps(step.steps, path + QStringLiteral(".steps"), suffix + QStringLiteral(" (%1/%2)").arg(n).arg(step.times));
        }
        return;
    }
    StepResult result;
    result.path = path;
    result.name = step.name + suffix;
    result.kind = step.kind;
    const qint64 start = monotonicNowNs();
    switch (step.kind) {
    case PlanStep::Kind::Send:
        runSend(step, result);
        break;
    case PlanStep::Kind::Expect:
        runExpect(step, result);
        break;
    case PlanStep::Kind::Poll:
        runPoll(step, result);
        break;
    case PlanStep::Kind::Wait: {
        QEventLoop loop;
        QTimer::singleShot(int(step.waitMs), &loop, &QEventLoop::quit);
        m_waitLoop = &loop;
        loop.exec();
        m_waitLoop = nullptr;
        if (m_result.interrupted) {
            // Cut short by the user, not by the device: not run to the end, so skipped.
            result.outcome = StepResult::Outcome::Skipped;
            result.reasons.append(QStringLiteral("interrupted after %1 of %2 ms").arg((monotonicNowNs() - start) / 1'000'000).arg(step.waitMs));
        } else {
            result.reasons.append(QStringLiteral("waited %1 ms").arg(step.waitMs));
        }
        break;
    }
    case PlanStep::Kind::Repeat:
        break;
    }
    result.elapsedNs = monotonicNowNs() - start;
    report(result);
}

std::optional<RequestItem> PlanRunner::item(const SessionRequest &request, QString *error)
{
    const SessionRequest::Bytes bytes = request.wireBytes(m_url, m_transactionId++);
    if (!bytes.ok()) {
        *error = QStringLiteral("%1: %2").arg(bytes.parameter, bytes.error);
        return std::nullopt;
    }
    RequestItem item = RequestItem::forLink(bytes.bytes, m_url, request.name);
    if (m_target.timeoutMs > 0)
        item.timeoutMs = m_target.timeoutMs;
    item.retries = m_target.retries;
    return item;
}

void PlanRunner::check(const StepExpectation &expectation, const Transaction &t, StepResult &result) const
{
    const ExpectationCheck::Outcome outcome = ExpectationCheck::check(expectation, t, m_url.framing(), m_url.delimited.enabled);
    result.outcome = outcome.passed() ? StepResult::Outcome::Passed : StepResult::Outcome::Failed;
    result.reasons = outcome.passed() ? outcome.checks : outcome.failures;
}

void PlanRunner::runSend(const PlanStep &step, StepResult &result)
{
    m_last.reset();
    const SessionRequest *request = step.requestName.isEmpty() ? &step.request : m_document.request(step.requestName);
    QString error;
    const std::optional<RequestItem> it = request ? item(*request, &error) : std::nullopt;
    if (!it) {
        result.outcome = StepResult::Outcome::Error;
        result.reasons.append(request ? error : QStringLiteral("no request named '%1'").arg(step.requestName));
        return;
    }
    const std::optional<Transaction> t = m_engine->sendAndWait(*it);
    if (!t) {
        result.outcome = StepResult::Outcome::Error;
        result.reasons.append(QStringLiteral("the engine did not record the request in time"));
        return;
    }
    result.detail = exchangeText(*t);
    if (t->status == TransactionStatus::LinkError) {
        // A link that refused (or failed) before the request was written sent nothing.
        result.detail = t->writeNs > 0 ? QStringLiteral("sent %1, then the link failed").arg(HexText::format(t->request))
                                       : QStringLiteral("not sent (the link failed first): %1").arg(HexText::format(t->request));
        result.outcome = StepResult::Outcome::Error;
        result.reasons.append(t->problem);
        m_result.linkFailed = true;
        m_result.linkMessage = t->problem;
        return;
    }
    m_last = t;
    check(step.expect, *t, result);
}

void PlanRunner::runExpect(const PlanStep &step, StepResult &result)
{
    if (!m_last) {
        result.outcome = StepResult::Outcome::Failed;
        result.reasons.append(QStringLiteral("no answer to check: the send step before did not run"));
        return;
    }
    result.detail = exchangeText(*m_last);
    check(step.expect, *m_last, result);
}

void PlanRunner::runPoll(const PlanStep &step, StepResult &result)
{
    PollSettings settings;
    for (const QString &name : step.poll.requests) {
        QString error;
        const SessionRequest *request = m_document.request(name);
        const std::optional<RequestItem> it = request ? item(*request, &error) : std::nullopt;
        if (!it) {
            result.outcome = StepResult::Outcome::Error;
            result.reasons.append(request ? error : QStringLiteral("no request named '%1'").arg(name));
            return;
        }
        settings.items.append(*it);
    }
    settings.intervalNs = step.poll.intervalMs * 1'000'000;
    settings.count = step.poll.count;
    settings.durationNs = step.poll.durationMs * 1'000'000;
    QString linkMessage;
    QObject context;
    QObject::connect(m_engine.get(), &TransactionEngine::linkMessage, &context,
                     [&linkMessage](const QString &message) { linkMessage = message; });
    m_engine->startPoll(settings);
    const std::optional<PollReport> report = m_engine->waitForFinished();
    if (!report || report->runs.isEmpty()) {
        result.outcome = StepResult::Outcome::Error;
        result.reasons.append(QStringLiteral("the poll did not finish"));
        return;
    }
    const Statistics &stats = report->runs.constFirst().statistics.overall();
    if (m_result.interrupted) {
        result.outcome = StepResult::Outcome::Skipped;
        result.reasons.append(QStringLiteral("interrupted: the poll was stopped after %1 transactions").arg(stats.count()));
        return;
    }
    result.detail = QStringLiteral("%1 transactions, %2 ok, %3 failed").arg(stats.count()).arg(stats.ok()).arg(stats.failed());
    if (!stats.latency().isEmpty())
        result.detail += QStringLiteral(", latency median %1, p95 %2, max %3")
                             .arg(msText(stats.latency().medianNs()), msText(stats.latency().percentileNs(95)),
                                  msText(stats.latency().maxNs()));
    if (stats.count() > 0 && stats.linkErrors() == stats.count()) {
        result.outcome = StepResult::Outcome::Error;
        m_result.linkFailed = true;
        m_result.linkMessage = linkMessage.isEmpty() ? QStringLiteral("every request of the poll ended in a link error") : linkMessage;
        result.reasons.append(m_result.linkMessage);
        return;
    }
    QStringList failures;
    QStringList checks;
    if (step.bounds.isEmpty()) {
        if (stats.failed() == 0)
            checks.append(QStringLiteral("every transaction ok"));
        else
            failures.append(QStringLiteral("%1 of %2 transactions failed (give bounds to allow some)").arg(stats.failed()).arg(stats.count()));
    }
    for (const PollBound &b : step.bounds) {
        const std::optional<double> measured = b.measure(stats);
        const QString seen = b.describe(stats);
        if (measured && b.holds(*measured))
            checks.append(QStringLiteral("%1 (%2)").arg(b.text, seen));
        else
            failures.append(QStringLiteral("%1 does not hold: %2").arg(b.text, seen));
    }
    result.outcome = failures.isEmpty() ? StepResult::Outcome::Passed : StepResult::Outcome::Failed;
    result.reasons = failures.isEmpty() ? checks : failures;
}

} // namespace mbscope
