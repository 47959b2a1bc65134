#include "replaycontroller.h"

#include "link/linkcontroller.h"
#include "replaydifferencesmodel.h"
#include "replayserver.h"
#include "replayworker.h"

#include "capture/captureanalysis.h"
#include "capture/exchangesource.h"
#include "engine/transactionengine.h"
#include "replay/replayscript.h"
#include "session/capturesourcepath.h"

#include <QtCore/QFileInfo>
#include <QtCore/QThread>

namespace mbscope {

// What the reading thread hands back: everything is made there and only read here afterwards.
struct ReplayController::Loaded {
    QString source;
    QString path;
    ExchangeSourceReport report;
    std::shared_ptr<ReplayScript> script = std::make_shared<ReplayScript>();
    QList<Transaction> transactions;
    Statistics statistics;
};

namespace {

QString msText(qint64 ns)
{
    return QString::number(double(ns) / 1e6, 'f', 3);
}

} // namespace

ReplayController::ReplayController(LinkController *link, QObject *parent)
    : QObject(parent), m_link(link), m_differences(new ReplayDifferencesModel(this)), m_server(new ReplayServer(this))
{
    qRegisterMetaType<mbscope::ReplayOutcome>();
    qRegisterMetaType<mbscope::ReplayResult>();
    connect(m_server, &ReplayServer::servingChanged, this, &ReplayController::busyChanged);
}

ReplayController::~ReplayController()
{
    if (m_worker) {
        QMetaObject::invokeMethod(m_worker, &ReplayWorker::stop, Qt::QueuedConnection);
        // Ends the runner's local loops too: the request in flight is not waited for.
        m_replayThread->quit();
        m_replayThread->wait();
        delete m_worker;
        delete m_replayThread;
    }
    if (m_loading) {
        m_loading->wait();
        delete m_loading;
    }
}

bool ReplayController::openSource(const QString &source)
{
    if (m_loading || m_worker) {
        Q_EMIT sourceFailed(m_loading ? tr("A capture is still being read.") : tr("Stop the replay before opening another capture."));
        return false;
    }
    QString path;
    QString error;
    if (!CaptureSourcePath::resolve(source, &path, &error)) {
        Q_EMIT sourceFailed(error);
        return false;
    }
    auto loaded = std::make_shared<Loaded>();
    loaded->source = source;
    loaded->path = path;
    const CaptureOptions options = m_options;
    // A million transactions take seconds to read: never on the GUI thread.
    m_loading = QThread::create([loaded, options] {
        CaptureAnalysis analysis;
        loaded->report = ExchangeSource::read(loaded->path, options, [&](const CaptureExchange &exchange) {
            analysis.add(exchange);
            loaded->script->add(exchange);
            if (exchange.kind == CaptureExchange::Kind::Transaction)
                loaded->transactions.append(exchange.transaction);
        });
        loaded->statistics = analysis.statistics();
    });
    m_loading->setObjectName(QStringLiteral("mbscope capture reader"));
    connect(m_loading, &QThread::finished, this, [this, loaded] { onLoaded(loaded); });
    m_loading->start();
    Q_EMIT busyChanged();
    return true;
}

void ReplayController::onLoaded(const std::shared_ptr<Loaded> &loaded)
{
    m_loading->wait();
    delete m_loading;
    m_loading = nullptr;
    const ExchangeSourceReport &report = loaded->report;
    if (!report.isReadable()) {
        Q_EMIT busyChanged();
        Q_EMIT sourceFailed(tr("%1 cannot be read: %2").arg(loaded->path, report.error));
        return;
    }
    m_source = loaded->source;
    m_title = QFileInfo(loaded->source).fileName();
    m_script = loaded->script;
    m_transactionCount = loaded->transactions.size();
    m_statistics = loaded->statistics;
    const LatencySamples &latency = m_statistics.latency();
    m_summary = tr("%1 (%2): transactions %3, ok %4, failed %5")
                    .arg(m_title, report.kindName())
                    .arg(m_transactionCount)
                    .arg(m_statistics.ok())
                    .arg(m_statistics.failed());
    if (!latency.isEmpty())
        m_summary = tr("%1; latency median %2 ms, p95 %3 ms, max %4 ms")
                        .arg(m_summary, msText(latency.medianNs()), msText(latency.percentileNs(95.0)), msText(latency.maxNs()));
    if (!report.error.isEmpty())
        m_summary = tr("%1. The file is damaged: %2; everything before it was read.").arg(m_summary, report.error);
    if (m_script->isEmpty() && report.kind == ExchangeSourceReport::Kind::Capture)
        m_summary = tr("%1. No Modbus requests were found on the ports looked at: set the Modbus TCP and RTU ports.").arg(m_summary);
    Q_EMIT busyChanged();
    Q_EMIT sourceOpened(m_summary);
    Q_EMIT captureAnalysed(m_title, loaded->transactions);
}

bool ReplayController::startReplay(double speed, bool sendWrites, QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_worker)
        return refuse(tr("A replay is already running."));
    if (m_loading)
        return refuse(tr("The capture is still being read."));
    if (!m_script || m_script->isEmpty())
        return refuse(tr("Open a capture or a session with recorded requests first."));
    if (!m_link->isConnected())
        return refuse(tr("Connect to the device to replay to first."));
    if (m_link->isPolling())
        return refuse(tr("Stop the poll first: a replay sends one request at a time, as they were recorded."));
    const LinkUrl target = m_link->url();
    if (target.delimited.enabled)
        return refuse(tr("%1 is a delimited link: it carries no Modbus framing to replay into.").arg(target.toString()));
    // One client at a time on a serial port or on many device servers: the window's link is
    // closed and opens again on its next request.
    if (m_link->engine())
        m_link->engine()->closeLink();

    m_lastResult.reset();
    m_replaySummary.clear();
    m_differences->reset(m_script, target.framing());
    m_replayThread = new QThread;
    m_replayThread->setObjectName(QStringLiteral("mbscope replay"));
    m_worker = new ReplayWorker(m_script, target, speed, sendWrites);
    m_worker->moveToThread(m_replayThread);
    connect(m_replayThread, &QThread::started, m_worker, &ReplayWorker::run);
    connect(m_worker, &ReplayWorker::outcomeReady, this, &ReplayController::onOutcome);
    connect(m_worker, &ReplayWorker::finished, this, &ReplayController::onReplayFinished);
    m_replayThread->start();
    Q_EMIT replayStarted();
    Q_EMIT busyChanged();
    return true;
}

void ReplayController::stopReplay()
{
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, &ReplayWorker::stop, Qt::QueuedConnection);
}

void ReplayController::onOutcome(const ReplayOutcome &outcome)
{
    m_differences->appendOutcome(outcome);
    Q_EMIT outcomeReplayed(outcome);
    Q_EMIT transactionsReplayed({outcome.replayed});
}

void ReplayController::onReplayFinished(const ReplayResult &result, const QString &linkProblem)
{
    m_replayThread->quit();
    m_replayThread->wait();
    delete m_worker;
    m_worker = nullptr;
    delete m_replayThread;
    m_replayThread = nullptr;
    m_lastResult = result;
    m_replaySummary = m_differences->countsText();
    if (!linkProblem.isEmpty())
        m_replaySummary = tr("The replay stopped: %1. %2").arg(linkProblem, m_replaySummary);
    else if (result.interrupted)
        m_replaySummary = tr("Stopped after %1 of %2 requests. %3").arg(result.outcomes.size()).arg(m_script->size()).arg(m_replaySummary);
    if (!result.skippedWrites.isEmpty())
        m_replaySummary += QLatin1Char(' ') + tr("Writes not sent: %1 (%2).")
                                                  .arg(result.skippedWrites.size())
                                                  .arg(RecordedWrite::placesText(result.skippedWrites));
    if (!result.recorded.latency().isEmpty() || !result.replayed.latency().isEmpty())
        m_replaySummary += QLatin1Char('\n') + result.latencyLine();
    Q_EMIT busyChanged();
    Q_EMIT replayFinished(m_replaySummary);
}

bool ReplayController::startServing(const QString &url, ReplayResponder::Unrecorded unrecorded, double speed, QString *error)
{
    if (!m_script || m_script->isEmpty()) {
        if (error)
            *error = tr("Open a capture or a session with recorded answers first.");
        return false;
    }
    return m_server->start(*m_script, url, unrecorded, speed, error);
}

void ReplayController::stopServing()
{
    m_server->stop();
}

QString ReplayController::servingText() const
{
    if (!m_server->isServing())
        return tr("Not serving.");
    const ReplayResponder::Counters c = m_server->counters();
    return tr("Serving the recorded answers of %1 on %2 (distinct requests: %3). Answers served: %4, silences kept: %5, "
              "requests never recorded: %6.")
        .arg(m_title, m_server->boundUrl().toString())
        .arg(m_server->distinctRequests())
        .arg(c.served)
        .arg(c.silences)
        .arg(c.unrecorded);
}

} // namespace mbscope
