#include "taprunner.h"

#include "sim/faultinjector.h"
#include "sim/simendpoint.h"
#include "sim/simfaulthook.h"
#include "sim/simulator.h"
#include "tap/tapforwarder.h"
#include "traffic/trafficlog.h"

#include <QtCore/QMetaObject>
#include <QtCore/QThread>
#include <QtCore/QTimer>

namespace mbscope {

namespace {

constexpr int kBatchIntervalMs = 33; // as the engine hands its batches over

// The traffic list keeps what it shows; the log of a tap the window does not record keeps what
// the recording's would (RollingCapture's limits).
TrafficLog::Limits ownLimits()
{
    TrafficLog::Limits limits;
    limits.maxEntries = 200'000;
    limits.maxBytes = quint64(32) << 20;
    return limits;
}

} // namespace

TapRunner::TapRunner(const TapSetup &setup, QObject *parent)
    : QObject(parent)
    , m_setup(setup)
{
    qRegisterMetaType<mbscope::TrafficFrame>();
    qRegisterMetaType<QList<mbscope::TrafficFrame>>();
    qRegisterMetaType<mbscope::TapCounters>();
    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("mbscope tap"));
    m_simulator = new Simulator;
    m_forwarder = new TapForwarder(setup.settings);
    m_simulator->setRemote(m_forwarder);
    if (setup.faults) {
        m_injector = std::make_unique<FaultInjector>();
        m_injector->setRules(*setup.faults);
        m_simulator->setFaultHook(faultHookFor(m_injector.get()));
    }
    connect(m_forwarder, &TapForwarder::targetOpened, this, &TapRunner::targetOpened);
    connect(m_forwarder, &TapForwarder::targetMessage, this, &TapRunner::targetMessage);
}

TapRunner::~TapRunner()
{
    blockSignals(true); // whoever listened may be half destroyed already
    stop();
}

bool TapRunner::listen(QString *error)
{
    if (m_running || !m_simulator)
        return false;
    for (const LinkUrl &url : std::as_const(m_setup.listen)) {
        QString why;
        SimEndpoint *endpoint = m_simulator->listen(url, SimEndpointOptions{}, &why);
        if (!endpoint) {
            if (error)
                *error = why.isEmpty() ? tr("%1: cannot listen").arg(url.toString()) : why;
            return false;
        }
        m_endpoints.append(endpoint->name());
    }
    return true;
}

void TapRunner::start(TrafficLog *log)
{
    if (m_running || !m_simulator)
        return;
    if (!log) {
        m_ownLog = std::make_unique<TrafficLog>(ownLimits());
        log = m_ownLog.get();
    }
    m_log = log;
    m_next = log->appended();
    m_simulator->setTrafficLog(log);
    m_forwarder->setTrafficLog(log);
    m_running = true;
    m_anchor = new QObject;
    auto *timer = new QTimer(m_anchor);
    timer->setInterval(kBatchIntervalMs);
    connect(timer, &QTimer::timeout, m_anchor, [this] { publish(); });
    m_thread->start();
    m_simulator->moveToThread(m_thread);
    m_forwarder->moveToThread(m_thread);
    m_anchor->moveToThread(m_thread);
    QMetaObject::invokeMethod(m_anchor, [timer] { timer->start(); }, Qt::QueuedConnection);
}

void TapRunner::stop()
{
    if (!m_simulator)
        return;
    Simulator *simulator = m_simulator;
    TapForwarder *forwarder = m_forwarder;
    QList<TrafficFrame> last;
    QStringList links;
    TapCounters counters;
    int waiting = 0;
    QObject *anchor = m_anchor;
    auto teardown = [&] {
        if (anchor)
            qDeleteAll(anchor->children()); // the batch timer stops
        // Nobody is asked any more: the masters' connections close, then the targets' links
        // (the forwarder's engines); requests still waiting get no answer.
        simulator->setRemote(nullptr);
        simulator->closeAll();
        counters = forwarder->counters();
        waiting = forwarder->waiting();
        delete forwarder;
        if (m_log)
            last = takeFrames(&links);
        simulator->setTrafficLog(nullptr);
        delete simulator;
    };
    if (m_running) {
        // Sockets and timers are deleted in the thread they belong to, then the thread ends.
        QMetaObject::invokeMethod(anchor, teardown, Qt::BlockingQueuedConnection);
        m_thread->quit();
        m_thread->wait();
    } else {
        teardown();
    }
    delete anchor;
    m_anchor = nullptr;
    m_simulator = nullptr;
    m_forwarder = nullptr;
    m_log = nullptr;
    const bool wasRunning = std::exchange(m_running, false);
    if (!wasRunning)
        return;
    if (!last.isEmpty())
        Q_EMIT framesLogged(last, links);
    Q_EMIT countersChanged(counters, waiting);
}

QList<TrafficFrame> TapRunner::takeFrames(QStringList *links)
{
    const quint64 end = m_log->appended();
    if (end <= m_next)
        return {};
    QList<TrafficFrame> frames = m_log->copy(m_next, qsizetype(end - m_next));
    m_next = end;
    *links = m_log->links();
    // Which links are the masters' (the endpoints' URLs): their requests came in and their
    // answers went out; read as the masters saw them, a request is out and its answer in.
    QList<bool> masters;
    masters.reserve(links->size());
    for (const QString &link : std::as_const(*links))
        masters.append(isMasterLink(link));
    for (TrafficFrame &frame : frames) {
        if (frame.link >= masters.size() || !masters.at(frame.link))
            continue;
        if (frame.direction == TrafficDirection::In) {
            frame.direction = TrafficDirection::Out;
            if (frame.verdict == TrafficVerdict::Ok)
                frame.verdict = TrafficVerdict::Sent; // a request: its verdict comes with its answer
        } else {
            frame.direction = TrafficDirection::In;
        }
    }
    return frames;
}

void TapRunner::publish()
{
    QStringList links;
    const QList<TrafficFrame> frames = takeFrames(&links);
    if (frames.isEmpty())
        return;
    Q_EMIT framesLogged(frames, links);
    Q_EMIT countersChanged(m_forwarder->counters(), m_forwarder->waiting());
}

} // namespace mbscope
