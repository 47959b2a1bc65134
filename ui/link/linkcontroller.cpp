#include "linkcontroller.h"

#include "buslistener.h"
#include "taprunner.h"

#include "engine/pollsettings.h"
#include "exchange/requestitem.h"
#include "exchange/statistics.h"
#include "engine/transactionengine.h"
#include "traffic/trafficmetadata.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>

namespace mbscope {

namespace {

EngineCounters operator+(EngineCounters a, const EngineCounters &b)
{
    a.requestsSent += b.requestsSent;
    a.transactions += b.transactions;
    a.retries += b.retries;
    a.late += b.late;
    a.unsolicitedFrames += b.unsolicitedFrames;
    a.duplicateFrames += b.duplicateFrames;
    a.skippedRuns += b.skippedRuns;
    a.skippedBytes += b.skippedBytes;
    a.bytesIn += b.bytesIn;
    a.bytesOut += b.bytesOut;
    a.connects += b.connects;
    a.linkErrors += b.linkErrors;
    a.abandoned += b.abandoned;
    a.cycles += b.cycles;
    a.overruns += b.overruns;
    return a;
}

} // namespace

LinkController::LinkController(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<mbscope::Transaction>();
    qRegisterMetaType<QList<mbscope::Transaction>>();
    qRegisterMetaType<QList<mbscope::TrafficFrame>>();
    qRegisterMetaType<mbscope::EngineProgress>();
    qRegisterMetaType<mbscope::PollReport>();
    qRegisterMetaType<mbscope::TapCounters>();
    qRegisterMetaType<mbscope::TapSetup>();
}

LinkController::~LinkController()
{
    dropEngine();
}

void LinkController::dropEngine()
{
    m_engine.reset();
    m_listener.reset();
    if (m_tap) {
        m_tap->stop(); // its last frames reach the list before the recording closes
        m_tap.reset();
    }
    if (m_capture) {
        Q_EMIT trafficLogChanged(nullptr); // the watches and scans let go first
        m_capture->finish();
        m_capture.reset();
        Q_EMIT recordingChanged({}, {});
    }
}

void LinkController::countFrames(const QList<TrafficFrame> &frames)
{
    EngineCounters add;
    for (const TrafficFrame &frame : frames) {
        if (frame.direction == TrafficDirection::Out) {
            ++add.requestsSent;
            add.bytesOut += quint64(frame.bytes.size());
        } else {
            add.bytesIn += quint64(frame.bytes.size());
        }
    }
    m_countersBefore = m_countersBefore + add;
    m_counters = m_counters + add;
    Q_EMIT countersChanged(m_counters);
}

void LinkController::countTransactions(const QList<Transaction> &transactions)
{
    EngineCounters add;
    for (const Transaction &t : transactions) {
        if (t.status != TransactionStatus::Late) {
            ++add.requestsSent;
            add.bytesOut += quint64(t.request.size());
        }
        add.bytesIn += quint64(t.response.size());
    }
    m_countersBefore = m_countersBefore + add;
    m_counters = m_counters + add;
    Q_EMIT countersChanged(m_counters);
}

void LinkController::setRecording(bool enabled, const CaptureDirectory &directory, const RollingCapture::Policy &policy)
{
    m_recordingEnabled = enabled;
    m_captures = directory;
    m_capturePolicy = policy;
}

TrafficLog *LinkController::startRecording(const QString &target, const RollingCapture::Describe &describe)
{
    m_capture = std::make_unique<RollingCapture>(m_captures, m_capturePolicy);
    if (!m_capture->start(target, &m_recordingProblem, describe)) {
        m_capture.reset();
        Q_EMIT recordingChanged(QString(), m_recordingProblem);
        return nullptr;
    }
    // A journal that stops while frames still come (its next part cannot be made, a full disk)
    // is said at once, not found out when the recording is opened: from the writing engine's
    // thread to this one.
    const RollingCapture *capture = m_capture.get();
    m_capture->log()->setJournalStopped([this, capture](const QString &problem) {
        QMetaObject::invokeMethod(this, [this, capture, problem] {
            if (m_capture.get() == capture)
                onRecordingStopped(problem);
        }, Qt::QueuedConnection);
    });
    Q_EMIT recordingChanged(recordingPath(), m_recordingProblem);
    return m_capture->log();
}

void LinkController::onRecordingStopped(const QString &problem)
{
    m_recordingProblem = tr("the recording stopped: %1; what came before is in %2")
                             .arg(problem, QDir::toNativeSeparators(recordingPath()));
    Q_EMIT recordingChanged(recordingPath(), m_recordingProblem);
}

QString LinkController::recordingPath() const
{
    return m_capture ? m_capture->currentPath() : QString();
}

bool LinkController::keepRecordingAt(const QString &path, bool *copied, QString *error)
{
    *copied = false;
    if (!m_capture || (!m_engine && !m_tap)) {
        *error = tr("nothing is being recorded");
        return false;
    }
    if (m_capture->moveTo(path, error)) {
        Q_EMIT recordingChanged(m_capture->currentPath(), {});
        return true;
    }
    if (QFile::exists(path))
        return false;
    // Another file system: the frames so far reach the file, then a copy of it goes to path
    // (written beside it and renamed into place, so path is never half a journal).
    if (m_engine)
        m_engine->flushTrafficLog();
    else
        m_capture->log()->flush(); // the tap's thread writes into it: flush() takes the log's lock
    QFile source(m_capture->currentPath());
    QSaveFile target(path);
    if (!source.open(QIODevice::ReadOnly) || !target.open(QIODevice::WriteOnly)) {
        *error = tr("cannot copy %1 to %2: %3").arg(source.fileName(), path,
                                                     source.isOpen() ? target.errorString() : source.errorString());
        return false;
    }
    while (!source.atEnd())
        target.write(source.read(1 << 20));
    if (!target.commit()) {
        *error = tr("cannot copy %1 to %2: %3").arg(source.fileName(), path, target.errorString());
        return false;
    }
    *copied = true;
    return true;
}

void LinkController::resetEngine()
{
    // A fresh engine per target: its link, framer and matcher start clean, and a poll of the old
    // target cannot deliver answers that look like the new one's.
    m_countersBefore = m_counters;
    dropEngine();
    m_engine = std::make_unique<TransactionEngine>();
    if (m_linkFactory)
        m_engine->setLinkFactory(m_linkFactory);
    connect(m_engine.get(), &TransactionEngine::transactionsFinished, this, &LinkController::onTransactions);
    connect(m_engine.get(), &TransactionEngine::framesLogged, this, &LinkController::framesLogged);
    m_engine->setFramesPublished(true);
    connect(m_engine.get(), &TransactionEngine::progress, this, &LinkController::onProgress);
    connect(m_engine.get(), &TransactionEngine::linkMessage, this, &LinkController::onLinkMessage);
    connect(m_engine.get(), &TransactionEngine::linkOpened, this, [this] { setState(State::Connected, m_url.toString()); });
    connect(m_engine.get(), &TransactionEngine::finished, this, &LinkController::onPollFinished);
}

void LinkController::restartCounters()
{
    // Each connection counts from zero (issue 26 item 16: TX and RX went on from the connection
    // before, so the bytes shown were never this link's).
    m_counters = {};
    m_countersBefore = {};
    Q_EMIT countersChanged(m_counters);
}

void LinkController::connectTo(const LinkUrl &url)
{
    if (m_polling)
        stopPoll();
    resetEngine();
    restartCounters();
    m_url = url;
    m_engine->setTarget(url);
    m_recordingProblem.clear();
    if (m_recordingEnabled) {
        if (TrafficLog *log = startRecording(url.toString()))
            m_engine->setTrafficLog(log);
        if (m_capture)
            Q_EMIT trafficLogChanged(m_capture->log());
    }
    // Connect opens the link now: a closed port or a missing serial device is said here, not at
    // the first Send.
    setState(State::Ready, tr("%1: connecting\u2026").arg(url.toString()));
    m_engine->openLink();
}

void LinkController::listenTo(const LinkUrl &url)
{
    if (m_polling)
        stopPoll();
    dropEngine();
    restartCounters();
    m_url = url;
    m_recordingProblem.clear();
    TrafficLog *log = nullptr;
    if (m_recordingEnabled) {
        log = startRecording(url.toString());
    }
    m_listener = std::make_unique<BusListener>(url, log);
    if (log)
        Q_EMIT trafficLogChanged(log);
    connect(m_listener.get(), &BusListener::opened, this, [this] {
        setState(State::Connected, tr("%1: listening only (nothing is sent)").arg(m_url.toString()));
    });
    connect(m_listener.get(), &BusListener::failed, this, &LinkController::onLinkMessage);
    connect(m_listener.get(), &BusListener::transactionsObserved, this, &LinkController::onObserved);
    connect(m_listener.get(), &BusListener::unmatchedObserved, this,
            [this](const QList<TrafficFrame> &frames) { Q_EMIT framesLogged(frames, m_url.toString()); });
    setState(State::Ready, tr("%1: opening to listen").arg(url.toString()));
    m_listener->start();
}

void LinkController::tapTo(const TapSetup &setup)
{
    if (m_polling)
        stopPoll();
    dropEngine();
    restartCounters();
    // The target the bar shows: the route for every unit the others leave.
    m_url = setup.settings.routes.isEmpty() ? LinkUrl{} : setup.settings.routes.constLast().target;
    m_recordingProblem.clear();
    m_tap = std::make_unique<TapRunner>(setup);
    QString error;
    if (!m_tap->listen(&error)) {
        m_tap.reset();
        setState(State::Disconnected, tr("Not connected"));
        Q_EMIT tapFailed(error);
        return;
    }
    TrafficLog *log = nullptr;
    if (m_recordingEnabled) {
        // The journal says what the tap did, as `mbscope tap --record` does: it served masters
        // where it listens (role server: analyze reads that leg as the masters saw it), and
        // where each unit's requests went.
        const QStringList endpoints = m_tap->endpoints();
        const auto describe = [&setup, &endpoints](TrafficMetadata &metadata) {
            metadata.role = TrafficMetadata::Role::Server;
            metadata.listen = endpoints;
            QStringList routes;
            for (const TapRoute &route : setup.settings.routes)
                routes.append(route.describe());
            metadata.settings.insert(QStringLiteral("routes"), QJsonArray::fromStringList(routes));
            metadata.settings.insert(QStringLiteral("tap"), QJsonArray::fromStringList(setup.arguments()));
            metadata.target = setup.settings.routes.size() == 1 ? setup.settings.routes.constFirst().target.toString() : QString();
        };
        log = startRecording(QStringLiteral("tap ") + endpoints.value(0), describe);
    }
    connect(m_tap.get(), &TapRunner::framesLogged, this, &LinkController::onTapFrames);
    connect(m_tap.get(), &TapRunner::countersChanged, this, &LinkController::tapCountersChanged);
    connect(m_tap.get(), &TapRunner::targetOpened, this, [this] { setState(State::Connected, tapDescription()); });
    connect(m_tap.get(), &TapRunner::targetMessage, this, [this](const QString &target, const QString &message) {
        setState(State::Failed, tr("%1: %2").arg(target, message));
    });
    m_tap->start(log);
    setState(State::Connected, tapDescription());
}

QString LinkController::tapDescription() const
{
    if (!m_tap)
        return {};
    QStringList targets;
    for (const TapRoute &route : m_tap->setup().settings.routes)
        targets.append(route.target.toString());
    targets.removeDuplicates();
    QString text = tr("tap: masters at %1 \u2192 %2").arg(m_tap->endpoints().join(QStringLiteral(", ")),
                                                          targets.join(QStringLiteral(", ")));
    if (m_tap->setup().settings.readOnly)
        text += tr(" (read-only)");
    return text;
}

void LinkController::onTapFrames(const QList<TrafficFrame> &frames, const QStringList &links)
{
    // The status bar's TX and RX are the device leg's: what the tap sent its targets and got back.
    EngineCounters add;
    for (const TrafficFrame &frame : frames) {
        if (frame.link < links.size() && m_tap && m_tap->isMasterLink(links.at(frame.link)))
            continue;
        if (frame.direction == TrafficDirection::Out) {
            ++add.requestsSent;
            add.bytesOut += quint64(frame.bytes.size());
        } else {
            if (!frame.bytes.isEmpty())
                ++add.transactions;
            add.bytesIn += quint64(frame.bytes.size());
        }
    }
    m_counters = m_counters + add;
    Q_EMIT countersChanged(m_counters);
    Q_EMIT tapFramesLogged(frames, links);
}

void LinkController::onObserved(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    m_counters.transactions += quint64(transactions.size());
    Q_EMIT countersChanged(m_counters);
    Q_EMIT transactionsFinished(transactions);
    Q_EMIT latestTransaction(transactions.constLast());
}

void LinkController::disconnectLink()
{
    if (m_listener || m_tap) {
        m_countersBefore = m_counters;
        dropEngine();
        setState(State::Disconnected, tr("Not connected"));
        return;
    }
    if (!m_engine)
        return;
    if (m_polling)
        stopPoll();
    m_engine->closeLink();
    m_countersBefore = m_counters;
    dropEngine();
    setState(State::Disconnected, tr("Not connected"));
}

quint64 LinkController::send(const QByteArray &bytes)
{
    if (!m_engine || bytes.isEmpty())
        return 0;
    return m_engine->send(item(bytes));
}

RequestItem LinkController::item(const QByteArray &bytes) const
{
    // Whoever sends on the window's link (Send, Poll, the register table's writes and reads
    // back), each request gets the connection's next MBAP transaction id from the engine.
    RequestItem item = RequestItem::forLink(bytes, m_url);
    item.engineNumbered = true;
    return item;
}

bool LinkController::startPoll(const QByteArray &bytes, int intervalMs, quint64 count)
{
    if (!m_engine || bytes.isEmpty())
        return false;
    PollSettings settings;
    settings.items = {item(bytes)};
    settings.intervalNs = qint64(qMax(0, intervalMs)) * 1000000;
    settings.count = count;
    // A poll left running all day: its latencies past the first 100,000 go into bins.
    settings.exactLatencyLimit = LatencySamples::kLongRunExactLimit;
    m_engine->startPoll(settings);
    m_polling = true;
    Q_EMIT pollingChanged(true);
    return true;
}

bool LinkController::startSweep(const QByteArray &bytes, const QList<int> &intervalsMs, quint64 count)
{
    if (!m_engine || bytes.isEmpty() || intervalsMs.isEmpty())
        return false;
    SweepSettings settings;
    settings.poll.items = {item(bytes)};
    settings.poll.count = count;
    settings.poll.exactLatencyLimit = LatencySamples::kLongRunExactLimit;
    for (const int ms : intervalsMs)
        settings.intervalsNs.append(qint64(qMax(0, ms)) * 1000000);
    m_engine->startSweep(settings);
    m_polling = true;
    Q_EMIT pollingChanged(true);
    return true;
}

void LinkController::stopPoll()
{
    if (!m_engine || !m_polling)
        return;
    m_engine->stop();
}

QString LinkController::describe(const PollReport &report)
{
    quint64 count = 0;
    quint64 ok = 0;
    quint64 failed = 0;
    qint64 minNs = 0;
    qint64 maxNs = 0;
    double weightedMeanNs = 0;
    qint64 answered = 0;
    for (const PollRun &run : report.runs) {
        const Statistics &s = run.statistics.overall();
        count += s.count();
        ok += s.ok();
        failed += s.failed();
        const LatencySamples &latency = s.latency();
        if (latency.isEmpty())
            continue;
        minNs = answered == 0 ? latency.minNs() : qMin(minNs, latency.minNs());
        maxNs = qMax(maxNs, latency.maxNs());
        weightedMeanNs += latency.meanNs() * double(latency.count());
        answered += latency.count();
    }
    QString text = tr("Poll %1: %2 transactions, %3 ok, %4 failed")
                       .arg(report.stopped ? tr("stopped") : tr("finished"))
                       .arg(count)
                       .arg(ok)
                       .arg(failed);
    if (answered > 0)
        text += tr("; latency min %1 ms, mean %2 ms, max %3 ms")
                    .arg(double(minNs) / 1e6, 0, 'f', 2)
                    .arg(weightedMeanNs / double(answered) / 1e6, 0, 'f', 2)
                    .arg(double(maxNs) / 1e6, 0, 'f', 2);
    return text;
}

void LinkController::onTransactions(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    Q_EMIT transactionsFinished(transactions);
    const Transaction &latest = transactions.constLast();
    if (latest.status == TransactionStatus::LinkError)
        setState(State::Failed, latest.problem.isEmpty() ? m_message : latest.problem);
    else if (latest.status != TransactionStatus::Broadcast)
        setState(State::Connected, m_url.toString());
    Q_EMIT latestTransaction(latest);
}

void LinkController::onProgress(const EngineProgress &progress)
{
    m_counters = m_countersBefore + progress.counters;
    Q_EMIT countersChanged(m_counters);
    Q_EMIT progressChanged(progress);
}

void LinkController::onLinkMessage(const QString &message)
{
    setState(State::Failed, message);
}

void LinkController::onPollFinished(const PollReport &report)
{
    m_polling = false;
    Q_EMIT pollingChanged(false);
    Q_EMIT pollFinished(report);
}

void LinkController::setState(State state, const QString &message)
{
    if (state == m_state && message == m_message)
        return;
    m_state = state;
    m_message = message;
    Q_EMIT stateChanged(state, message);
}

} // namespace mbscope
