#include "watchlinkpoller.h"

#include "watch/watchblock.h"
#include "watch/watchdecoder.h"

#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"
#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>

namespace mbscope {

namespace {

qint64 nowMs()
{
    return QDateTime::currentMSecsSinceEpoch();
}

QString exceptionText(quint8 code)
{
    return QStringLiteral("exception 0x%1 (%2)")
        .arg(QString::number(code, 16).rightJustified(2, QLatin1Char('0')).toUpper(), QString::fromLatin1(exceptionName(code)));
}

} // namespace

WatchLinkPoller::WatchLinkPoller(const WatchLinkSettings &settings, const QList<Watch> &watches, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_timer(this)
{
    const LinkUrl::Result parsed = LinkUrl::parse(settings.target);
    m_url = parsed.url;
    m_urlError = parsed.error;
    for (const Watch &w : watches) {
        Entry e;
        e.watch = w;
        e.pdu = WatchBlock::requestPdu(w.definition);
        e.rules = WatchRuleEvaluator(w.definition);
        e.counters.watch = w.index;
        e.counters.watchName = w.definition.name;
        m_entries.append(e);
    }
    m_state.target = settings.target;
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &WatchLinkPoller::onTimer);
}

WatchLinkPoller::~WatchLinkPoller() = default;

void WatchLinkPoller::start()
{
    if (!m_url) {
        m_phase = Phase::Stopped;
        setState(WatchLinkState::State::Down, m_urlError);
        return;
    }
    EngineOptions options;
    // Each answer decides the next turn: it is wanted at once, not in the next ~30 Hz batch.
    options.batchIntervalMs = 0;
    // The device's pace is the engine's, as for every other talker (poll, the window): no request
    // sooner than gapMs after the exchange before it, none sooner than warmUpMs after the link
    // opens (each time it opens).
    options.requestGap = std::chrono::milliseconds(m_settings.gapMs);
    options.warmUp = std::chrono::milliseconds(m_settings.warmUpMs);
    m_engine = std::make_unique<TransactionEngine>();
    m_engine->setTarget(*m_url, options);
    if (m_log)
        m_engine->setTrafficLog(m_log);
    if (m_framesPublished) {
        m_engine->setFramesPublished(true);
        connect(m_engine.get(), &TransactionEngine::framesLogged, this, &WatchLinkPoller::framesLogged);
    }
    connect(m_engine.get(), &TransactionEngine::transactionsFinished, this, &WatchLinkPoller::onTransactions);
    connect(m_engine.get(), &TransactionEngine::linkOpened, this, &WatchLinkPoller::onLinkOpened);
    connect(m_engine.get(), &TransactionEngine::linkMessage, this, &WatchLinkPoller::onLinkMessage);
    const qint64 now = monotonicNowNs();
    for (Entry &e : m_entries)
        e.dueNs = now;
    setState(WatchLinkState::State::Connecting);
    if (m_settings.warmUpMs > 0) {
        // The device ignores requests this soon after a connection opens: open it first (the
        // state says Connecting, then Up), and the engine holds the first request its warm-up.
        m_phase = Phase::Connecting;
        m_timer.start(m_url->connectTimeoutMs + 3000);
        m_engine->openLink();
        return;
    }
    m_phase = Phase::Idle;
    pump();
}

void WatchLinkPoller::setTrafficLog(TrafficLog *log)
{
    m_log = log;
    if (m_engine)
        m_engine->setTrafficLog(log);
}

void WatchLinkPoller::stop()
{
    if (m_phase == Phase::Stopped && !m_engine)
        return;
    m_phase = Phase::Stopped;
    m_timer.stop();
    if (m_engine) {
        disconnect(m_engine.get(), nullptr, this, nullptr);
        m_engine.reset(); // closes the link; a request in flight is abandoned
    }
    m_inFlight = 0;
    while (!m_writes.empty()) {
        const PendingWrite w = m_writes.front();
        m_writes.pop_front();
        Q_EMIT writeFinished(w.id, w.watch, w.address, false, QStringLiteral("the watches stopped before the write was sent"));
    }
    setState(WatchLinkState::State::Stopped);
}

void WatchLinkPoller::write(quint64 id, int watch, quint16 address, const QList<quint16> &words)
{
    for (const Entry &e : std::as_const(m_entries)) {
        if (e.watch.index != watch)
            continue;
        QString error;
        const QByteArray pdu = WatchBlock::writePdu(e.watch.definition, address, words, &error);
        if (pdu.isEmpty()) {
            Q_EMIT writeFinished(id, watch, address, false, error);
            return;
        }
        if (m_phase == Phase::Stopped) {
            Q_EMIT writeFinished(id, watch, address, false, QStringLiteral("the watches are not running"));
            return;
        }
        m_writes.push_back(PendingWrite{id, watch, address, pdu, e.watch.definition.unit});
        if (m_phase == Phase::Idle)
            pump();
        return;
    }
    Q_EMIT writeFinished(id, watch, address, false, QStringLiteral("no watch %1 on %2").arg(watch).arg(m_settings.target));
}

RequestItem WatchLinkPoller::requestFor(const QByteArray &pdu, quint8 unit)
{
    AduOptions adu;
    adu.framing = m_url->framing();
    adu.unitId = unit;
    adu.transactionId = ++m_transactionId;
    RequestItem item = RequestItem::forLink(AduBuilder::complete(pdu, adu), *m_url);
    if (m_settings.timeoutMs > 0)
        item.timeoutMs = m_settings.timeoutMs;
    else if (m_url->responseTimeoutMs <= 0)
        item.timeoutMs = 1000;
    item.retries = m_settings.retries;
    return item;
}

int WatchLinkPoller::nextEntry() const
{
    int best = -1;
    for (int i = 0; i < m_entries.size(); ++i) {
        if (!m_entries.at(i).watch.definition.enabled)
            continue;
        if (best < 0 || m_entries.at(i).dueNs < m_entries.at(best).dueNs)
            best = i;
    }
    return best;
}

void WatchLinkPoller::armTimer(qint64 waitNs)
{
    m_timer.start(int(qBound<qint64>(0, (waitNs + 999999) / 1000000, 24LL * 3600 * 1000)));
}

void WatchLinkPoller::pump()
{
    if (m_phase != Phase::Idle || !m_engine)
        return;
    if (!m_writes.empty()) {
        m_inFlightWrite = m_writes.front();
        m_writes.pop_front();
        m_inFlightEntry = -1;
        m_phase = Phase::Busy;
        m_inFlight = m_engine->send(requestFor(m_inFlightWrite.pdu, m_inFlightWrite.unit));
        return;
    }
    const int next = nextEntry();
    if (next < 0)
        return;
    Entry &e = m_entries[next];
    const qint64 now = monotonicNowNs();
    if (e.dueNs > now) {
        armTimer(e.dueNs - now);
        return;
    }
    // Start to start: the next poll is due an interval after this one was due. A watch that
    // missed a whole interval (the link was busy with others, or slow) starts again as soon
    // as it can, and that counts as an overrun.
    const qint64 intervalNs = e.watch.definition.intervalMs * 1000000;
    e.dueNs += intervalNs;
    if (e.dueNs < now) {
        if (intervalNs > 0)
            ++e.counters.overruns;
        e.dueNs = now;
    }
    m_inFlightEntry = next;
    m_phase = Phase::Busy;
    m_inFlight = m_engine->send(requestFor(e.pdu, e.watch.definition.unit));
}

void WatchLinkPoller::onTimer()
{
    switch (m_phase) {
    case Phase::Idle:
        pump();
        break;
    case Phase::Backoff:
        m_phase = Phase::Connecting;
        setState(WatchLinkState::State::Connecting, m_state.message);
        // The link's own connect timeout ends a connect; this guards against one that never says.
        m_timer.start(m_url->connectTimeoutMs + 3000);
        m_engine->openLink();
        break;
    case Phase::Connecting:
        failOpen(QStringLiteral("%1: the link did not open").arg(m_settings.target));
        break;
    case Phase::Busy:
    case Phase::Stopped:
        break;
    }
}

void WatchLinkPoller::onTransactions(const QList<Transaction> &transactions)
{
    for (const Transaction &t : transactions) {
        if (m_phase != Phase::Busy || t.id != m_inFlight || t.status == TransactionStatus::Late)
            continue;
        m_inFlight = 0;
        if (m_inFlightEntry >= 0)
            finishPoll(t);
        else
            finishWrite(t);
        if (m_phase == Phase::Stopped)
            return;
        if (t.status == TransactionStatus::LinkError) {
            linkLost(t.problem);
            continue;
        }
        m_phase = Phase::Idle; // the engine keeps the gap after this exchange (EngineOptions::requestGap)
        pump();
    }
}

void WatchLinkPoller::finishPoll(const Transaction &t)
{
    Entry &e = m_entries[m_inFlightEntry];
    const WatchDefinition &def = e.watch.definition;
    WatchCounters &c = e.counters;
    WatchSample s;
    s.watch = e.watch.index;
    s.watchName = def.name;
    s.timeMs = nowMs();
    s.poll = ++e.polls;
    s.latencyNs = t.sentNs > 0 && t.doneNs > 0 ? t.latencyNs() : -1;
    s.requestBytes = t.writeNs > 0 ? t.request.size() : 0;
    s.answerBytes = t.response.size();
    s.exceptionCode = t.exceptionCode;
    // An Enron answer carries four bytes per register it was asked for, which the engine's
    // verdict (two per register) calls malformed: the watch reads it by its own rule.
    const bool readable = t.status == TransactionStatus::Ok
        || (t.status == TransactionStatus::Malformed && WatchBlock::wordsPerAddress(def) == 2)
        || t.status == TransactionStatus::Exception;
    if (readable) {
        const WatchAnswer answer = WatchBlock::readAnswer(def, AduBuilder::parse(t.response, m_url->framing()).pdu);
        if (answer.ok) {
            s.status = WatchSample::Status::Ok;
            s.words = answer.words;
            s.bits = answer.bits;
            s.values = WatchDecoder::decode(def, answer.words, answer.bits);
        } else if (answer.exceptionCode != 0) {
            s.status = WatchSample::Status::Exception;
            s.exceptionCode = answer.exceptionCode;
            s.error = exceptionText(answer.exceptionCode);
        } else {
            s.status = WatchSample::Status::Error;
            s.error = t.status == TransactionStatus::Malformed ? t.problem : answer.error;
        }
    } else if (t.status == TransactionStatus::Timeout) {
        s.status = WatchSample::Status::Timeout;
        s.error = t.problem.isEmpty() ? QStringLiteral("no answer") : t.problem;
    } else if (t.status == TransactionStatus::CrcError) {
        s.status = WatchSample::Status::CrcError;
        s.error = t.problem;
    } else {
        s.status = WatchSample::Status::Error;
        s.error = t.problem.isEmpty() ? transactionStatusName(t.status) : t.problem;
        s.linkError = t.status == TransactionStatus::LinkError;
    }

    ++c.polls;
    switch (s.status) {
    case WatchSample::Status::Ok:
        ++c.ok;
        c.lastOkMs = s.timeMs;
        break;
    case WatchSample::Status::Exception:
        ++c.exceptions;
        ++c.exceptionsByCode[s.exceptionCode];
        break;
    case WatchSample::Status::Timeout:
        ++c.timeouts;
        break;
    case WatchSample::Status::CrcError:
        ++c.crcErrors;
        break;
    case WatchSample::Status::Error:
        if (t.status == TransactionStatus::LinkError)
            ++c.linkErrors;
        else
            ++c.otherErrors;
        break;
    }
    if (s.status != WatchSample::Status::Ok) {
        c.lastError = s.error;
        c.lastErrorMs = s.timeMs;
    }
    if (s.status == WatchSample::Status::Ok || s.status == WatchSample::Status::Exception)
        c.addLatency(s.latencyNs);
    c.reconnects = m_state.reconnects;

    QList<WatchRuleEvent> events = e.rules.evaluate(s.values, s.timeMs);
    for (WatchRuleEvent &event : events) {
        event.watch = e.watch.index;
        if (event.fired)
            ++c.ruleFirings;
    }
    Q_EMIT sampled(s, c);
    for (const WatchRuleEvent &event : std::as_const(events))
        Q_EMIT ruleChanged(event);
}

void WatchLinkPoller::finishWrite(const Transaction &t)
{
    const PendingWrite w = m_inFlightWrite;
    QString message;
    const bool ok = t.status == TransactionStatus::Ok;
    if (ok)
        message = QStringLiteral("written");
    else if (t.status == TransactionStatus::Exception)
        message = exceptionText(t.exceptionCode);
    else
        message = t.problem.isEmpty() ? transactionStatusName(t.status) : t.problem;
    // Read the written value back with the watch's next turn.
    for (Entry &e : m_entries) {
        if (ok && e.watch.index == w.watch)
            e.dueNs = qMin(e.dueNs, monotonicNowNs());
    }
    Q_EMIT writeFinished(w.id, w.watch, w.address, ok, message);
}

void WatchLinkPoller::failOpen(const QString &message)
{
    // An attempt to open the link again that failed is a poll lost for each watch of the link:
    // it is counted and logged as one, so that an outage shows in the counters and the CSV rows.
    const qint64 timeMs = nowMs();
    for (Entry &e : m_entries) {
        if (!e.watch.definition.enabled)
            continue;
        WatchSample s;
        s.watch = e.watch.index;
        s.watchName = e.watch.definition.name;
        s.timeMs = timeMs;
        s.poll = ++e.polls;
        s.status = WatchSample::Status::Error;
        s.error = message;
        s.linkError = true;
        ++e.counters.polls;
        ++e.counters.linkErrors;
        e.counters.lastError = message;
        e.counters.lastErrorMs = timeMs;
        Q_EMIT sampled(s, e.counters);
    }
    linkLost(message);
}

void WatchLinkPoller::linkLost(const QString &message)
{
    ++m_state.failures;
    setState(WatchLinkState::State::Down, message);
    m_backoffMs = m_backoffMs == 0 ? qMax(1, m_settings.reconnectMinMs)
                                   : qMin(m_backoffMs * 2, qMax(m_settings.reconnectMinMs, m_settings.reconnectMaxMs));
    m_phase = Phase::Backoff;
    m_engine->closeLink();
    setState(WatchLinkState::State::Backoff, message, m_backoffMs);
    m_timer.start(m_backoffMs);
}

void WatchLinkPoller::onLinkOpened()
{
    ++m_opens;
    // A device that hangs up after each answer (close=each) gets a new connection per request by
    // design: that is no reconnect, and the link, up all along, says nothing new.
    const bool planned = m_url->closeAfterAnswer && m_state.state == WatchLinkState::State::Up;
    if (m_opens > 1 && !planned)
        ++m_state.reconnects;
    for (Entry &e : m_entries)
        e.counters.reconnects = m_state.reconnects;
    m_backoffMs = 0;
    if (!planned)
        setState(WatchLinkState::State::Up);
    if (m_phase == Phase::Connecting) {
        m_timer.stop();
        m_phase = Phase::Idle; // the engine holds the first request the warm-up (EngineOptions::warmUp)
        pump();
    }
}

void WatchLinkPoller::onLinkMessage(const QString &message)
{
    m_state.message = message;
    if (m_phase == Phase::Connecting) {
        m_timer.stop();
        failOpen(message);
    }
}

void WatchLinkPoller::setState(WatchLinkState::State state, const QString &message, int retryInMs)
{
    m_state.state = state;
    if (!message.isEmpty() || state == WatchLinkState::State::Up)
        m_state.message = message;
    m_state.retryInMs = retryInMs;
    m_state.timeMs = nowMs();
    Q_EMIT linkStateChanged(m_state);
}

} // namespace mbscope

#include "moc_watchlinkpoller.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
