#include "timingscanner.h"

#include "unitscanner.h"

#include "engine/transactionengine.h"
#include "exchange/requestitem.h"
#include "protocol/adubuilder.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QSet>
#include <QtCore/QTimer>

#include <algorithm>
#include <memory>
#include <vector>

namespace mbscope {

namespace {

// An answer that says the device served the request: data, or an exception about the request
// itself. Busy (06), acknowledge (05) and the gateway's 0A/0B say it did not.
bool served(const Transaction &t)
{
    if (t.status == TransactionStatus::Ok)
        return true;
    return t.status == TransactionStatus::Exception && t.exceptionCode != 0x05 && t.exceptionCode != 0x06
        && t.exceptionCode != 0x0A && t.exceptionCode != 0x0B;
}

} // namespace

QString TimingScanSettings::problem() const
{
    if (url.delimited.enabled)
        return QStringLiteral("a delimited link carries no Modbus: there is nothing to time");
    if (function < 1 || function > 4)
        return QStringLiteral("function %1 is not a read: 01, 02, 03 or 04").arg(function);
    if (timeoutMs < 1 || requestsPerGap < 1 || pipelineDepth < 1 || maxClients < 1 || gapsMs.isEmpty())
        return QStringLiteral("the timeout, the counts and the gaps must be positive");
    return {};
}

int TimingReport::recommendedGapMs() const
{
    // Twice the shortest gap that had no error, at least 1 ms when it needed any: a margin for a
    // busier device than the one measured.
    if (shortestCleanGapMs < 0)
        return gaps.isEmpty() ? 0 : gaps.constFirst().gapMs * 2;
    return shortestCleanGapMs == 0 ? 0 : shortestCleanGapMs * 2;
}

int TimingReport::recommendedTimeoutMs() const
{
    // Three times the slowest answer seen, rounded up to 10 ms, and never under 100 ms.
    const qint64 ms = (maxLatencyUs * 3 + 999) / 1000;
    return int(qMax<qint64>(100, (ms + 9) / 10 * 10));
}

TimingScanner::TimingScanner(QObject *parent)
    : QObject(parent)
    , m_channel(new ProbeChannel(this))
{
}

QByteArray TimingScanner::readPdu(int quantity) const
{
    return UnitScanner::readPdu(m_settings.function, m_settings.address, quint16(quantity));
}

std::optional<TimingReport> TimingScanner::run(const TimingScanSettings &settings)
{
    if (!settings.problem().isEmpty())
        return std::nullopt;
    m_settings = settings;
    m_stopRequested = false;
    m_channel->setTarget(settings.url);
    TimingReport report;
    warmup(report);
    if (report.firstAnswerMs < 0 || m_stopRequested)
        return report;
    gaps(report);
    if (!m_stopRequested)
        largestRead(report);
    // The probe channel's connection would count among the clients: the rest opens its own.
    m_channel->closeLink();
    if (!m_stopRequested)
        pipelining(report);
    if (!m_stopRequested)
        clients(report);
    return report;
}

void TimingScanner::warmup(TimingReport &report)
{
    Q_EMIT step(QStringLiteral("first answer after connecting"));
    m_channel->closeLink();
    m_channel->setGapMs(20);
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < m_settings.warmupLimitMs && !m_stopRequested) {
        const std::optional<ProbeChannel::Answer> a = m_channel->ask(m_settings.unit, readPdu(1), qMin(m_settings.timeoutMs, 500));
        if (!a)
            return;
        if (served(a->transaction)) {
            report.firstAnswerMs = clock.elapsed();
            report.maxLatencyUs = qMax(report.maxLatencyUs, a->transaction.latencyNs() / 1000);
            return;
        }
        ++report.warmupFailures;
    }
}

void TimingScanner::gaps(TimingReport &report)
{
    for (const int gap : m_settings.gapsMs) {
        if (m_stopRequested)
            return;
        Q_EMIT step(QStringLiteral("gap %1 ms").arg(gap));
        m_channel->setGapMs(gap);
        TimingReport::GapTrial trial;
        trial.gapMs = gap;
        for (int i = 0; i < m_settings.requestsPerGap && !m_stopRequested; ++i) {
            const std::optional<ProbeChannel::Answer> a = m_channel->ask(m_settings.unit, readPdu(1), m_settings.timeoutMs);
            if (!a)
                return;
            if (served(a->transaction)) {
                ++trial.ok;
                trial.maxLatencyUs = qMax(trial.maxLatencyUs, a->transaction.latencyNs() / 1000);
            } else {
                ++trial.failed;
            }
        }
        report.gaps.append(trial);
        report.maxLatencyUs = qMax(report.maxLatencyUs, trial.maxLatencyUs);
        if (trial.failed > 0)
            return; // errors started: shorter gaps are not asked
        report.shortestCleanGapMs = gap;
    }
}

void TimingScanner::largestRead(TimingReport &report)
{
    Q_EMIT step(QStringLiteral("largest read"));
    m_channel->setGapMs(qMax(0, report.recommendedGapMs()));
    const int specMax = m_settings.function <= 2 ? 2000 : 125; // V1.1b3, 6.1-6.4
    const auto answers = [this](int q) {
        const std::optional<ProbeChannel::Answer> a = m_channel->ask(m_settings.unit, readPdu(q), m_settings.timeoutMs);
        return a && a->transaction.status == TransactionStatus::Ok;
    };
    int ok = 0;
    int refused = specMax + 1;
    if (answers(specMax)) {
        ok = specMax;
    } else {
        while (refused - ok > 1 && !m_stopRequested) {
            const int mid = (ok + refused) / 2;
            if (answers(mid))
                ok = mid;
            else
                refused = mid;
        }
    }
    report.largestQuantity = ok;
    report.largestAnswerPdu = ok == 0 ? 0 : 2 + (m_settings.function <= 2 ? (ok + 7) / 8 : 2 * ok);
}

namespace {

// Waits for the transactions of ids from one engine (or waitMs); the ones that came.
QList<Transaction> collect(TransactionEngine &engine, const QSet<quint64> &ids, int waitMs)
{
    QList<Transaction> out;
    QEventLoop loop;
    QObject::connect(&engine, &TransactionEngine::transactionsFinished, &loop, [&](const QList<Transaction> &batch) {
        for (const Transaction &t : batch) {
            if (ids.contains(t.id) && t.status != TransactionStatus::Late)
                out.append(t);
        }
        if (out.size() >= ids.size())
            loop.quit();
    });
    QTimer::singleShot(waitMs, &loop, &QEventLoop::quit);
    loop.exec();
    return out;
}

// Opens the engine's link and waits until it is open, then settleMs more (the device's warm-up
// and its gap: what a new connection must wait before it is answered at all).
void openAndSettle(TransactionEngine &engine, int connectMs, qint64 settleMs)
{
    QEventLoop loop;
    QObject::connect(&engine, &TransactionEngine::linkOpened, &loop, &QEventLoop::quit);
    QObject::connect(&engine, &TransactionEngine::linkMessage, &loop, &QEventLoop::quit);
    QTimer::singleShot(connectMs, &loop, &QEventLoop::quit);
    engine.openLink();
    loop.exec();
    if (settleMs > 0) {
        QEventLoop wait;
        QTimer::singleShot(int(settleMs), &wait, &QEventLoop::quit);
        wait.exec();
    }
}

} // namespace

qint64 TimingScanner::settleMs(const TimingReport &report) const
{
    return (report.warmupFailures > 0 ? report.firstAnswerMs : 0) + report.recommendedGapMs();
}

void TimingScanner::pipelining(TimingReport &report)
{
    if (m_settings.url.framing() != Framing::Tcp && m_settings.url.framing() != Framing::Udp)
        return;
    Q_EMIT step(QStringLiteral("pipelined requests"));
    TransactionEngine engine;
    EngineOptions options;
    options.pipelineDepth = m_settings.pipelineDepth;
    options.batchIntervalMs = 1;
    engine.setTarget(m_settings.url, options);
    openAndSettle(engine, m_settings.url.connectTimeoutMs, settleMs(report));
    QSet<quint64> ids;
    for (int i = 0; i < m_settings.pipelineDepth; ++i) {
        RequestItem item = RequestItem::forLink(AduBuilder::mbap(readPdu(1), m_settings.unit, quint16(i + 1)), m_settings.url);
        item.timeoutMs = m_settings.timeoutMs;
        ids.insert(engine.send(item));
    }
    const QList<Transaction> done = collect(engine, ids, m_settings.timeoutMs * 2 + m_settings.url.connectTimeoutMs);
    report.pipelineSent = m_settings.pipelineDepth;
    for (const Transaction &t : done)
        report.pipelineOk += served(t) ? 1 : 0;
}

void TimingScanner::clients(TimingReport &report)
{
    if (m_settings.url.isSerial() || m_settings.url.isDatagram())
        return;
    Q_EMIT step(QStringLiteral("clients at once"));
    // One engine per client, each keeping its connection open: client k is asked while the
    // k - 1 before it are still connected.
    struct Held {
        std::unique_ptr<TransactionEngine> engine;
        int opened = 0; // connections made: more than one means the first was closed
    };
    std::vector<std::unique_ptr<Held>> held;
    const QByteArray adu = AduBuilder::complete(readPdu(1), AduOptions{m_settings.url.framing(), m_settings.unit, 1, 0});
    const auto ask = [&](Held &client) {
        RequestItem item = RequestItem::forLink(adu, m_settings.url);
        item.timeoutMs = m_settings.timeoutMs;
        const std::optional<Transaction> t = client.engine->sendAndWait(item);
        return t && served(*t);
    };
    for (int k = 1; k <= m_settings.maxClients && !m_stopRequested; ++k) {
        auto client = std::make_unique<Held>();
        client->engine = std::make_unique<TransactionEngine>();
        Held *c = client.get();
        connect(c->engine.get(), &TransactionEngine::linkOpened, this, [c] { ++c->opened; });
        EngineOptions options;
        options.batchIntervalMs = 1;
        c->engine->setTarget(m_settings.url, options);
        openAndSettle(*c->engine, m_settings.url.connectTimeoutMs, settleMs(report));
        const bool servedNew = ask(*c);
        report.clientsTried = k;
        if (!servedNew)
            break;
        report.clientsServed = k;
        held.push_back(std::move(client));
        if (held.size() < 2)
            continue;
        // A gateway that makes room by closing the client connected longest (extraClients
        // dropOldest) serves every new client: ask the oldest one again, after the gap the device
        // needs. Its connection gone (the request fails, or the engine had to connect again),
        // the one before this client was the last that fit.
        QEventLoop wait;
        QTimer::singleShot(std::max(20, report.recommendedGapMs()), &wait, &QEventLoop::quit);
        wait.exec();
        Held &oldest = *held.front();
        const int openedBefore = oldest.opened;
        if (!ask(oldest) || oldest.opened > openedBefore) {
            report.clientsServed = k - 1;
            report.oldestDropped = true;
            break;
        }
    }
}

} // namespace mbscope
