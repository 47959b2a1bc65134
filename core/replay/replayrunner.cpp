#include "replay/replayrunner.h"

#include "exchange/requestitem.h"
#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "replay/replayscript.h"
#include "transport/monotonicclock.h"

#include <QtCore/QEventLoop>
#include <QtCore/QTimer>

#include <chrono>

namespace mbscope {

namespace {

bool isMbap(Framing framing)
{
    return framing == Framing::Tcp || framing == Framing::Udp;
}

} // namespace

ReplayRunner::ReplayRunner(const ReplayScript &script, const LinkUrl &target, const EngineOptions &options, int timeoutMs)
    : m_script(script), m_target(target), m_timeoutMs(timeoutMs), m_engine(std::make_unique<TransactionEngine>())
{
    m_engine->setTarget(target, options);
}

void ReplayRunner::setTrafficLog(TrafficLog *log)
{
    m_engine->setTrafficLog(log);
}

ReplayRunner::~ReplayRunner() = default;

QByteArray ReplayRunner::wireBytes(const ReplayScript &script, qsizetype index, Framing framing)
{
    const ReplayExchange &e = script.exchanges().at(size_t(index));
    // MBAP over TCP and over UDP share their bytes, as RTU does over any link.
    if (e.framing == framing || (isMbap(e.framing) && isMbap(framing)))
        return e.recorded.request;
    AduOptions options;
    options.framing = framing;
    options.unitId = e.unitId;
    options.transactionId = quint16(index + 1);
    return AduBuilder::complete(e.requestPdu, options);
}

void ReplayRunner::waitUntil(qint64 dueNs)
{
    const qint64 waitNs = dueNs - monotonicNowNs();
    if (waitNs <= 0 || m_stopped)
        return;
    QEventLoop loop;
    m_waitLoop = &loop;
    QTimer::singleShot(std::chrono::milliseconds((waitNs + 999'999) / 1'000'000), Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
    m_waitLoop = nullptr;
}

void ReplayRunner::stop()
{
    m_stopped = true;
    if (m_waitLoop)
        m_waitLoop->quit();
}

ReplayResult ReplayRunner::run(const Observer &observer)
{
    ReplayResult result;
    result.target = m_target.toString();
    result.ignoredSelectors = m_ignore.selectors();
    const Framing framing = m_target.framing();
    const qint64 startNs = monotonicNowNs();
    for (qsizetype i = 0; i < m_script.size() && !m_stopped; ++i) {
        const ReplayExchange &e = m_script.exchanges().at(size_t(i));
        if (!m_sendWrites) {
            if (const auto write = RecordedWrite::of(i, e.unitId, e.requestPdu)) {
                result.skippedWrites.append(*write);
                continue;
            }
        }
        if (m_speed > 0)
            waitUntil(startNs + qint64(double(e.offsetNs) / m_speed));
        if (m_stopped)
            break;
        RequestItem item = RequestItem::forLink(wireBytes(m_script, i, framing), m_target);
        if (m_timeoutMs > 0)
            item.timeoutMs = m_timeoutMs;
        const std::optional<Transaction> t = m_engine->sendAndWait(item);
        ReplayOutcome outcome;
        outcome.index = i;
        if (t) {
            outcome.replayed = *t;
        } else {
            outcome.replayed.request = item.bytes;
            outcome.replayed.status = TransactionStatus::Timeout;
            outcome.replayed.problem = QStringLiteral("the engine did not report the request in time");
        }
        outcome.comparison = AnswerComparison::compare(e.recorded, e.framing, outcome.replayed, framing, m_ignore);
        result.recorded.add(e.recorded);
        result.replayed.add(outcome.replayed);
        result.outcomes.append(outcome);
        if (observer)
            observer(result.outcomes.constLast());
    }
    result.interrupted = m_stopped && result.outcomes.size() + result.skippedWrites.size() < m_script.size();
    result.elapsedNs = monotonicNowNs() - startNs;
    m_engine->closeLink();
    return result;
}

} // namespace mbscope
