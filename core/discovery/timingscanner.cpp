#include "timingscanner.h"

#include "profiledraft.h"
#include "unitscanner.h"

#include "engine/transactionengine.h"
#include "exchange/requestitem.h"
#include "protocol/adubuilder.h"
#include "profile/devicelimits.h"
#include "protocol/functionspec.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QThread>
#include <QtCore/QScopeGuard>
#include <QtCore/QSet>
#include <QtCore/QTimer>

#include <algorithm>
#include <memory>
#include <vector>

namespace mbscope {

namespace {

// An answer that says the device served the request: data, or an exception about the request
// itself. Busy (06), acknowledge (05) and the gateway's 0A/0B say it did not.
// A warm-up waited out with some to spare, as a client keeps it (DeviceLimits::clientWarmUp):
// the device counts from when it took the connection in, which can be after this end saw it open.
qint64 spared(qint64 warmUpMs)
{
    DeviceLimits limits;
    limits.warmUpMs = double(warmUpMs);
    return limits.clientWarmUp().count();
}

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
    if (url.hasPace())
        return QStringLiteral("the timing scan measures the device's own pace, which gap=, warmup= and close= of the target "
                              "would hide: leave them out of the target");
    if (function < 1 || function > 4)
        return QStringLiteral("function %1 is not a read: 01, 02, 03 or 04").arg(function);
    if (timeoutMs < 1 || requestsPerGap < 1 || pipelineDepth < 1 || maxClients < 1 || gapsMs.isEmpty())
        return QStringLiteral("the timeout, the counts and the gaps must be positive");
    if (maxDurationMs < 1)
        return QStringLiteral("the time limit must be positive");
    return {};
}

int TimingReport::recommendedGapMs() const
{
    // Twice the shortest gap that had no error, at least 1 ms when it needed any: a margin for a
    // busier device than the one measured.
    if (gapsHeldByWarmUp)
        return 0; // the warm-up of each new connection keeps the requests apart
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

QJsonObject TimingReport::profileLimits(quint8 function) const
{
    QJsonObject limits;
    if (firstAnswerMs < 0)
        return limits; // never answered: nothing was measured
    // A gap is the device's least only when a shorter one was tried and had errors; 0 ms clean
    // says it has none. Gaps that all had errors, or a stop before any error, say nothing.
    bool shorterFailed = false;
    for (const GapTrial &trial : gaps)
        shorterFailed = shorterFailed || (trial.failed > 0 && trial.gapMs < shortestCleanGapMs);
    if (shortestCleanGapMs > 0 && shorterFailed)
        limits.insert(QStringLiteral("minGapMs"), shortestCleanGapMs);
    else if (shortestCleanGapMs == 0)
        limits.insert(QStringLiteral("minGapMs"), QJsonValue::Null);
    limits.insert(QStringLiteral("warmUpMs"), warmupFailures > 0 ? QJsonValue(double(pauseAfterConnectMs())) : QJsonValue(QJsonValue::Null));
    if (gapReconnects >= 0 && gapAnswered >= 3)
        limits.insert(QStringLiteral("closesAfterAnswer"), closesAfterAnswer() ? QJsonValue(true) : QJsonValue(QJsonValue::Null));
    if (clientsTried > 0 && clientsServed > 0 && clientsServed < clientsTried) {
        limits.insert(QStringLiteral("maxClients"), clientsServed);
        limits.insert(QStringLiteral("extraClients"), oldestDropped ? QStringLiteral("dropOldest") : QStringLiteral("refuse"));
    }
    const int specMax = QuantityLimits::maxQuantity(function);
    if (largestQuantity > 0 && largestFound)
        limits.insert(QStringLiteral("maxQuantity"),
                      QJsonObject{{DeviceLimits::functionKey(function),
                                   largestQuantity < specMax ? QJsonValue(largestQuantity) : QJsonValue(QJsonValue::Null)}});
    return limits;
}

QMap<int, int> TimingReport::answeredReads(quint8 function) const
{
    QMap<int, int> answered;
    if (largestQuantity > 0)
        answered.insert(function, largestQuantity);
    return answered;
}

TimingScanner::TimingScanner(QObject *parent)
    : QObject(parent)
    , m_channel(new ProbeChannel(this))
{
    connect(m_channel, &ProbeChannel::framesLogged, this, [this](const QList<TrafficFrame> &frames, const QString &link) {
        if (m_framesPublished)
            Q_EMIT framesLogged(frames, link);
    });
    connect(m_channel, &ProbeChannel::linkOpened, this, [this] { ++m_opens; });
}

QByteArray TimingScanner::readPdu(int quantity) const
{
    return UnitScanner::readPdu(m_settings.function, m_settings.address, quint16(quantity));
}

void TimingScanner::stop()
{
    m_stopRequested = true;
    if (m_report && m_end == JobEnd::Completed)
        m_end = JobEnd::Stopped;
    m_channel->cancel();
    Q_EMIT stopping();
}

bool TimingScanner::mayContinue(qint64 nextMs)
{
    if (m_end != JobEnd::Completed)
        return false;
    if (m_stopRequested)
        m_end = JobEnd::Stopped;
    else if (m_clock.elapsed() + nextMs > m_settings.maxDurationMs)
        m_end = JobEnd::TimeLimit;
    return m_end == JobEnd::Completed;
}

void TimingScanner::setTrafficLog(TrafficLog *log)
{
    // From the thread that shows the scan while the scanner lives in a job's thread (JobThread).
    if (thread() != QThread::currentThread() && thread()->isRunning()) {
        QMetaObject::invokeMethod(this, [this, log] { setTrafficLog(log); }, Qt::BlockingQueuedConnection);
        return;
    }
    m_log = log;
    m_channel->setTrafficLog(log);
}

void TimingScanner::observe(TransactionEngine &engine)
{
    if (m_log)
        engine.setTrafficLog(m_log);
    if (m_framesPublished) {
        engine.setFramesPublished(true);
        connect(&engine, &TransactionEngine::framesLogged, this, &TimingScanner::framesLogged);
    }
}

std::optional<ProbeChannel::Answer> TimingScanner::ask(int quantity, int timeoutMs, bool measured)
{
    QElapsedTimer took;
    took.start();
    std::optional<ProbeChannel::Answer> answer = m_channel->ask(m_settings.unit, readPdu(quantity), timeoutMs);
    if (answer && measured) {
        // What the step took beyond the gap the channel waited before sending.
        m_answeredMs += qMax<qint64>(0, took.elapsed() - m_channel->gapMs());
        ++m_answered;
    }
    return answer;
}

qint64 TimingScanner::answerMs() const
{
    return m_answered > 0 ? m_answeredMs / m_answered : m_settings.timeoutMs;
}

qint64 TimingScanner::stepCostMs(int index) const
{
    const qint64 answer = answerMs();
    // The gap the later parts keep: while the gaps are tried and none had errors yet, the one
    // they would give if every gap left is clean too (the common case); then the one measured.
    qint64 gap = 0;
    qint64 settle = 0;
    if (m_report) {
        bool errors = false;
        for (const TimingReport::GapTrial &trial : m_report->gaps)
            errors = errors || trial.failed > 0;
        gap = m_done < m_partStart[Largest] && !errors ? 2 * qint64(*std::min_element(m_settings.gapsMs.cbegin(), m_settings.gapsMs.cend())) : qMax(0, m_report->recommendedGapMs());
        settle = m_report->pauseAfterConnectMs() + gap;
    }
    if (index < m_partStart[Gaps])
        return 20 + answer; // the warm-up asks every 20 ms
    if (index < m_partStart[Largest])
        return m_settings.gapsMs.at((index - m_partStart[Gaps]) / m_settings.requestsPerGap) + answer;
    if (index < m_partStart[Pipeline])
        return gap + answer;
    if (index < m_partStart[Clients])
        return settle + answer;
    // Client k: a new connection settles and is asked; from the second on, the oldest is asked again.
    const int k = index - m_partStart[Clients] + 1;
    return settle + answer + (k >= 2 ? qMax<qint64>(20, gap) + answer : 0);
}

JobProgress TimingScanner::progress() const
{
    JobProgress p;
    p.total = m_partStart[PartCount];
    p.done = qMin(m_done, p.total);
    p.elapsedMs = m_clock.isValid() ? m_clock.elapsed() : 0;
    qint64 left = 0;
    for (int i = p.done; i < p.total; ++i)
        left += stepCostMs(i);
    p.remainingMs = qMin(left, qMax<qint64>(0, m_settings.maxDurationMs - p.elapsedMs));
    return p;
}

void TimingScanner::beginPart(Part part, const QString &what)
{
    Q_EMIT step(what);
    m_done = qMax(m_done, m_partStart[part]);
    Q_EMIT progressChanged(progress());
}

void TimingScanner::stepDone()
{
    ++m_done;
    Q_EMIT progressChanged(progress());
}

void TimingScanner::endPart(Part part)
{
    m_done = qMax(m_done, m_partStart[part + 1]);
    Q_EMIT progressChanged(progress());
}

std::optional<TimingReport> TimingScanner::run(const TimingScanSettings &settings)
{
    if (!settings.problem().isEmpty())
        return std::nullopt;
    m_settings = settings;
    m_stopRequested = false;
    m_end = JobEnd::Completed;
    m_done = 0;
    m_answeredMs = 0;
    m_answered = 0;
    m_channel->setTarget(settings.url);
    // The plan: one step for the first answer, every request of every gap, the largest read's
    // first request and its bisection at worst (ceil(log2(spec maximum + 1)) more), the pipelined
    // burst (MBAP links), every client (stream links).
    const int specMax = QuantityLimits::maxQuantity(quint8(settings.function));
    int bisection = 0;
    for (int span = specMax + 1; span > 1; span = (span + 1) / 2)
        ++bisection;
    const bool mbap = settings.url.framing() == Framing::Tcp || settings.url.framing() == Framing::Udp;
    const bool stream = !settings.url.isSerial() && !settings.url.isDatagram();
    const int counts[PartCount] = {1, int(settings.gapsMs.size()) * settings.requestsPerGap, 1 + bisection, mbap ? 1 : 0,
                                   stream ? settings.maxClients : 0};
    for (int i = 0; i < PartCount; ++i)
        m_partStart[i + 1] = m_partStart[i] + counts[i];
    TimingReport report;
    m_report = &report;
    m_clock.start();
    warmup(report); // its start emits the first progress, at 0
    if (report.firstAnswerMs >= 0) {
        if (m_end == JobEnd::Completed)
            gaps(report);
        if (m_end == JobEnd::Completed)
            largestRead(report);
        // The probe channel's connection would count among the clients: the rest opens its own.
        m_channel->closeLink();
        // A device that hangs up after each answer serves no burst and keeps no client: not
        // measured (they would read as limits it does not have).
        if (report.closesAfterAnswer() && m_end == JobEnd::Completed) {
            Q_EMIT step(QStringLiteral("the device closes the connection after each answer: pipelining and clients at once not measured"));
            endPart(Clients);
        }
        if (m_end == JobEnd::Completed && !report.closesAfterAnswer())
            pipelining(report);
        if (m_end == JobEnd::Completed && !report.closesAfterAnswer())
            clients(report);
    }
    m_channel->closeLink();
    JobProgress last = progress();
    last.remainingMs = 0; // ended: nothing is left, whatever was not asked
    m_report = nullptr;
    Q_EMIT progressChanged(last);
    return report;
}

void TimingScanner::warmup(TimingReport &report)
{
    beginPart(Warmup, QStringLiteral("first answer after connecting"));
    m_channel->closeLink();
    m_channel->setGapMs(20);
    const int timeoutMs = qMin(m_settings.timeoutMs, 500);
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < m_settings.warmupLimitMs && mayContinue(20 + timeoutMs)) {
        const std::optional<ProbeChannel::Answer> a = ask(1, timeoutMs, false);
        if (!a)
            return;
        if (served(a->transaction)) {
            report.firstAnswerMs = clock.elapsed();
            report.maxLatencyUs = qMax(report.maxLatencyUs, a->transaction.latencyNs() / 1000);
            // Until the gaps are measured, the estimate takes this answer's time for every one.
            m_answeredMs += a->transaction.latencyNs() / 1'000'000;
            ++m_answered;
            if (report.warmupFailures > 0)
                narrowWarmUp(report, timeoutMs);
            endPart(Warmup);
            return;
        }
        ++report.warmupFailures;
    }
}

void TimingScanner::narrowWarmUp(TimingReport &report, int timeoutMs)
{
    // The first answer came one timeout after requests the device ignored: the warm-up lies
    // between 0 and that time. Each try is a new connection whose first request waits a given
    // time after it opened; halving the range to 10 ms takes about six of them.
    qint64 answered = report.firstAnswerMs;
    qint64 refused = 0;
    while (answered - refused > 10) {
        const qint64 wait = (answered + refused) / 2;
        if (!mayContinue(wait + timeoutMs))
            break;
        m_channel->closeLink();
        m_channel->setWarmUpMs(int(wait));
        const std::optional<ProbeChannel::Answer> a = ask(1, timeoutMs, false);
        if (!a)
            break;
        // Awake is any answer, a refusal too: a device still warming up says nothing, and one
        // asked too soon after the last request (its minGapMs, counted across connections)
        // answers busy, which is no warm-up.
        const TransactionStatus status = a->transaction.status;
        if (status == TransactionStatus::Ok || status == TransactionStatus::Exception)
            answered = wait;
        else
            refused = wait;
    }
    report.warmUpMs = answered;
    report.warmUpRefusedMs = refused;
    // Every connection the rest of the scan opens waits it out (a device that hangs up after each
    // answer is connected again for each request).
    m_channel->closeLink();
    m_channel->setWarmUpMs(int(spared(answered)));
}

void TimingScanner::gaps(TimingReport &report)
{
    beginPart(Gaps, QStringLiteral("gap %1 ms").arg(m_settings.gapsMs.constFirst()));
    // On a connection, how often the channel had to connect again for them (however this ends).
    const bool stream = !m_settings.url.isSerial() && !m_settings.url.isDatagram();
    const int opensBefore = m_opens;
    const auto reconnects = qScopeGuard([&] {
        if (stream)
            report.gapReconnects = m_opens - opensBefore;
    });
    for (const int gap : m_settings.gapsMs) {
        if (!mayContinue(gap + m_settings.timeoutMs))
            return;
        Q_EMIT step(QStringLiteral("gap %1 ms").arg(gap));
        m_channel->setGapMs(gap);
        TimingReport::GapTrial trial;
        trial.gapMs = gap;
        for (int i = 0; i < m_settings.requestsPerGap; ++i) {
            const std::optional<ProbeChannel::Answer> a =
                mayContinue(gap + m_settings.timeoutMs) ? ask(1, m_settings.timeoutMs) : std::nullopt;
            if (!a) {
                if (trial.ok + trial.failed > 0)
                    report.gaps.append(trial); // measured, but not all of it: no clean gap from it
                return;
            }
            if (served(a->transaction)) {
                ++trial.ok;
                ++report.gapAnswered;
                trial.maxLatencyUs = qMax(trial.maxLatencyUs, a->transaction.latencyNs() / 1000);
            } else {
                ++trial.failed;
            }
            stepDone();
        }
        report.gaps.append(trial);
        report.maxLatencyUs = qMax(report.maxLatencyUs, trial.maxLatencyUs);
        if (trial.failed > 0)
            break; // errors started: shorter gaps are not asked
        report.shortestCleanGapMs = gap;
        // A device that hangs up after each answer, whose every new connection waits its warm-up:
        // each request comes the warm-up after the one before, so no shorter gap can be asked.
        if (stream && report.pauseAfterConnectMs() > 0 && trial.ok >= 3 && m_opens - opensBefore >= trial.ok - 1) {
            report.gapsHeldByWarmUp = true;
            break;
        }
    }
    report.gapsComplete = true;
    endPart(Gaps);
}

void TimingScanner::largestRead(TimingReport &report)
{
    beginPart(Largest, QStringLiteral("largest read"));
    const int gap = qMax(0, report.recommendedGapMs());
    m_channel->setGapMs(gap);
    const int specMax = QuantityLimits::maxQuantity(quint8(m_settings.function));
    // Whether quantity q is answered; nullopt when it was not asked (stopped, or out of time).
    // A refusal notes whether it was for the quantity (exception 03): 02 says the read ran past
    // the device's map, which limits where, not how much.
    bool refusedForQuantity = false;
    const auto answers = [&](int q) -> std::optional<bool> {
        if (!mayContinue(gap + m_settings.timeoutMs))
            return std::nullopt;
        const std::optional<ProbeChannel::Answer> a = ask(q, m_settings.timeoutMs);
        if (!a)
            return std::nullopt;
        stepDone();
        if (a->transaction.status == TransactionStatus::Ok)
            return true;
        refusedForQuantity = a->transaction.status == TransactionStatus::Exception && a->transaction.exceptionCode == 0x03;
        return false;
    };
    int ok = 0;
    int refused = specMax + 1;
    bool refusedBy03 = false; // the refusal at `refused`
    const std::optional<bool> whole = answers(specMax);
    if (whole && *whole) {
        ok = specMax;
    } else if (whole) {
        refused = specMax;
        refusedBy03 = refusedForQuantity;
        while (refused - ok > 1) {
            const int mid = (ok + refused) / 2;
            const std::optional<bool> answered = answers(mid);
            if (!answered)
                break;
            if (*answered) {
                ok = mid;
            } else {
                refused = mid;
                refusedBy03 = refusedForQuantity;
            }
        }
    }
    report.largestQuantity = ok;
    // A limit of the device only when one more was refused for its quantity: a read refused for
    // running past the map (02) says where the map ends.
    report.largestFound = ok == specMax || (refused - ok == 1 && refusedBy03);
    report.largestEndsMap = ok < specMax && refused - ok == 1 && !refusedBy03;
    report.largestAnswerPdu = ok == 0 ? 0 : 2 + (m_settings.function <= 2 ? (ok + 7) / 8 : 2 * ok);
    if (m_end == JobEnd::Completed) {
        report.largestComplete = true;
        endPart(Largest);
    }
}

namespace {

// Waits for the transactions of ids from one engine (or waitMs); the ones that came.
QList<Transaction> collect(TransactionEngine &engine, const QSet<quint64> &ids, int waitMs, TimingScanner *scanner)
{
    QList<Transaction> out;
    QEventLoop loop;
    QObject::connect(scanner, &TimingScanner::stopping, &loop, &QEventLoop::quit);
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
void openAndSettle(TransactionEngine &engine, int connectMs, qint64 settleMs, TimingScanner *scanner)
{
    QEventLoop loop;
    QObject::connect(scanner, &TimingScanner::stopping, &loop, &QEventLoop::quit);
    QObject::connect(&engine, &TransactionEngine::linkOpened, &loop, &QEventLoop::quit);
    QObject::connect(&engine, &TransactionEngine::linkMessage, &loop, &QEventLoop::quit);
    QTimer::singleShot(connectMs, &loop, &QEventLoop::quit);
    engine.openLink();
    loop.exec();
    if (settleMs > 0) {
        QEventLoop wait;
        QObject::connect(scanner, &TimingScanner::stopping, &wait, &QEventLoop::quit);
        QTimer::singleShot(int(settleMs), &wait, &QEventLoop::quit);
        wait.exec();
    }
}

} // namespace

qint64 TimingScanner::settleMs(const TimingReport &report) const
{
    const qint64 pause = report.pauseAfterConnectMs();
    return (pause > 0 ? spared(pause) : 0) + report.recommendedGapMs();
}

void TimingScanner::pipelining(TimingReport &report)
{
    if (m_settings.url.framing() != Framing::Tcp && m_settings.url.framing() != Framing::Udp)
        return;
    if (!mayContinue(settleMs(report) + m_settings.timeoutMs))
        return;
    beginPart(Pipeline, QStringLiteral("pipelined requests"));
    TransactionEngine engine;
    EngineOptions options;
    options.pipelineDepth = m_settings.pipelineDepth;
    options.batchIntervalMs = 1;
    engine.setTarget(m_settings.url, options);
    observe(engine);
    const auto lastFrames = qScopeGuard([&engine, this] {
        if (m_framesPublished)
            engine.deliverPending();
    });
    openAndSettle(engine, m_settings.url.connectTimeoutMs, settleMs(report), this);
    if (m_stopRequested)
        return;
    QSet<quint64> ids;
    for (int i = 0; i < m_settings.pipelineDepth; ++i) {
        RequestItem item = RequestItem::forLink(AduBuilder::mbap(readPdu(1), m_settings.unit, quint16(i + 1)), m_settings.url);
        item.timeoutMs = m_settings.timeoutMs;
        ids.insert(engine.send(item));
    }
    const QList<Transaction> done = collect(engine, ids, m_settings.timeoutMs * 2 + m_settings.url.connectTimeoutMs, this);
    if (m_stopRequested)
        return;
    report.pipelineSent = m_settings.pipelineDepth;
    for (const Transaction &t : done)
        report.pipelineOk += served(t) ? 1 : 0;
    endPart(Pipeline);
}

void TimingScanner::clients(TimingReport &report)
{
    if (m_settings.url.isSerial() || m_settings.url.isDatagram())
        return;
    beginPart(Clients, QStringLiteral("clients at once"));
    // One engine per client, each keeping its connection open: client k is asked while the
    // k - 1 before it are still connected.
    struct Held {
        std::unique_ptr<TransactionEngine> engine;
        int opened = 0; // connections made: more than one means the first was closed
    };
    std::vector<std::unique_ptr<Held>> held;
    std::unique_ptr<Held> client;
    const auto lastFrames = qScopeGuard([&] { // the frames not yet delivered, before the engines go
        if (!m_framesPublished)
            return;
        for (const std::unique_ptr<Held> &h : held)
            h->engine->deliverPending();
        if (client)
            client->engine->deliverPending();
    });
    const QByteArray adu = AduBuilder::complete(readPdu(1), AduOptions{m_settings.url.framing(), m_settings.unit, 1, 0});
    const auto askClient = [&](Held &asked) {
        RequestItem item = RequestItem::forLink(adu, m_settings.url);
        item.timeoutMs = m_settings.timeoutMs;
        const std::optional<Transaction> t = asked.engine->sendAndWait(item);
        return t && served(*t);
    };
    for (int k = 1; k <= m_settings.maxClients; ++k) {
        const qint64 recheckMs = k >= 2 ? std::max(20, report.recommendedGapMs()) + m_settings.timeoutMs : 0;
        if (!mayContinue(settleMs(report) + m_settings.timeoutMs + recheckMs))
            return;
        client = std::make_unique<Held>();
        client->engine = std::make_unique<TransactionEngine>();
        Held *c = client.get();
        connect(c->engine.get(), &TransactionEngine::linkOpened, this, [c] { ++c->opened; });
        // Stop ends the request in flight: its link closed, the engine's wait ends.
        connect(this, &TimingScanner::stopping, c->engine.get(), [e = c->engine.get()] { e->closeLink(); });
        EngineOptions options;
        options.batchIntervalMs = 1;
        c->engine->setTarget(m_settings.url, options);
        observe(*c->engine);
        openAndSettle(*c->engine, m_settings.url.connectTimeoutMs, settleMs(report), this);
        const bool servedNew = !m_stopRequested && askClient(*c);
        if (m_stopRequested)
            return; // client k was not measured
        stepDone();
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
        connect(this, &TimingScanner::stopping, &wait, &QEventLoop::quit);
        QTimer::singleShot(std::max(20, report.recommendedGapMs()), &wait, &QEventLoop::quit);
        wait.exec();
        Held &oldest = *held.front();
        const int openedBefore = oldest.opened;
        const bool oldestServed = !m_stopRequested && askClient(oldest);
        if (m_stopRequested)
            return;
        if (!oldestServed || oldest.opened > openedBefore) {
            report.clientsServed = k - 1;
            report.oldestDropped = true;
            break;
        }
    }
}

} // namespace mbscope

#include "moc_timingscanner.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
