#include "transactionengine.h"

#include "enginecore.h"
#include "engineeventdispatcher.h"
#include "sweep.h"

#include <limits>

#include <QtCore/QCoreApplication>
#include <QtCore/QEventLoop>
#include <QtCore/QTimer>

namespace mbscope {

TransactionEngine::TransactionEngine(QObject *parent)
    : QObject(parent)
    , m_core(new EngineCore)
{
    qRegisterMetaType<mbscope::Transaction>();
    qRegisterMetaType<QList<mbscope::Transaction>>();
    qRegisterMetaType<QList<mbscope::TrafficFrame>>();
    qRegisterMetaType<mbscope::EngineProgress>();
    qRegisterMetaType<mbscope::PollReport>();
    m_thread.setObjectName(QStringLiteral("mbscope engine"));
    m_core->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_core, &QObject::deleteLater);
    connect(m_core->recorder(), &EngineRecorder::transactionsFinished, this, &TransactionEngine::transactionsFinished);
    connect(m_core->recorder(), &EngineRecorder::framesLogged, this, &TransactionEngine::framesLogged);
    connect(m_core->recorder(), &EngineRecorder::progress, this, &TransactionEngine::progress);
    connect(m_core, &EngineCore::linkMessage, this, &TransactionEngine::linkMessage);
    connect(m_core, &EngineCore::linkOpened, this, &TransactionEngine::linkOpened);
    // The engine thread's own dispatcher, lighter per turn than Qt's (see EngineEventDispatcher).
    m_thread.setEventDispatcher(new EngineEventDispatcher);
    m_thread.start();
}

TransactionEngine::~TransactionEngine()
{
    QMetaObject::invokeMethod(m_core, [this] {
        if (m_sweep) {
            disconnect(m_sweep, nullptr, this, nullptr);
            delete m_sweep;
            m_sweep = nullptr;
        }
        m_core->closeLink();
    }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void TransactionEngine::setLinkFactory(LinkFactory factory)
{
    QMetaObject::invokeMethod(m_core, [core = m_core, factory = std::move(factory)] { core->setLinkFactory(factory); },
                              Qt::QueuedConnection);
}

void TransactionEngine::setTarget(const LinkUrl &url, const EngineOptions &options)
{
    m_url = url;
    // What the device's pace may hold a request before it is written (sendAndWait waits it too).
    const EngineOptions paced = options.withPaceOf(url);
    m_paceWaitMs = std::chrono::ceil<std::chrono::milliseconds>(paced.requestGap + paced.warmUp).count();
    QMetaObject::invokeMethod(m_core, [core = m_core, url, options] { core->setTarget(url, options); }, Qt::QueuedConnection);
}

void TransactionEngine::setTrafficLog(TrafficLog *log)
{
    QMetaObject::invokeMethod(m_core, [core = m_core, log] { core->setTrafficLog(log); }, Qt::BlockingQueuedConnection);
}

void TransactionEngine::setFramesPublished(bool published)
{
    m_core->recorder()->setFramesPublished(published);
}

void TransactionEngine::deliverPending()
{
    QMetaObject::invokeMethod(m_core->recorder(), &EngineRecorder::flushBatch, Qt::BlockingQueuedConnection);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::MetaCall);
}

void TransactionEngine::flushTrafficLog()
{
    QMetaObject::invokeMethod(m_core, [core = m_core] { core->recorder()->flushLog(); }, Qt::BlockingQueuedConnection);
}

quint64 TransactionEngine::send(const RequestItem &item)
{
    const quint64 id = m_core->reserveId();
    QMetaObject::invokeMethod(m_core, [core = m_core, item, id] { core->submit(item, id); }, Qt::QueuedConnection);
    return id;
}

std::optional<Transaction> TransactionEngine::sendAndWait(const RequestItem &item, int waitMs)
{
    if (waitMs < 0)
        waitMs = int(std::min<qint64>((qint64(item.timeoutMs) + m_paceWaitMs) * (item.retries + 1) + m_url.connectTimeoutMs + 2000,
                                      std::numeric_limits<int>::max()));
    QEventLoop loop;
    std::optional<Transaction> result;
    quint64 id = 0;
    // The record comes at once through recorded(); the batch that carries it to the observers
    // would follow only when due (EngineOptions::batchIntervalMs), which a plan's back-to-back
    // sends would wait out every time. So the batch is flushed now, and the wait ends when it
    // arrives: whoever watches transactionsFinished has the transaction when this returns.
    const auto recordedConnection = connect(m_core->recorder(), &EngineRecorder::recorded, &loop, [&](const Transaction &t, quint64) {
        if (t.id == id && t.status != TransactionStatus::Late) {
            result = t;
            QMetaObject::invokeMethod(m_core->recorder(), &EngineRecorder::flushBatch, Qt::QueuedConnection);
        }
    });
    const auto batchConnection = connect(this, &TransactionEngine::transactionsFinished, &loop,
                                         [&](const QList<Transaction> &batch) {
                                             for (const Transaction &t : batch) {
                                                 if (t.id == id && t.status != TransactionStatus::Late) {
                                                     result = t;
                                                     loop.quit();
                                                 }
                                             }
                                         });
    id = send(item);
    QTimer::singleShot(waitMs, &loop, &QEventLoop::quit);
    loop.exec();
    disconnect(recordedConnection);
    disconnect(batchConnection);
    return result;
}

void TransactionEngine::startPoll(const PollSettings &settings)
{
    SweepSettings sweep;
    sweep.poll = settings;
    sweep.intervalsNs = {settings.intervalNs};
    startRuns(sweep, false);
}

void TransactionEngine::startSweep(const SweepSettings &settings)
{
    startRuns(settings, true);
}

void TransactionEngine::startRuns(const SweepSettings &settings, bool isSweep)
{
    QMetaObject::invokeMethod(m_core, [this, settings, isSweep] {
        if (m_sweep) {
            Sweep *old = m_sweep;
            m_sweep = nullptr;
            old->stop();
        }
        auto *sweep = new Sweep(m_core, settings, isSweep, m_core);
        m_sweep = sweep;
        connect(sweep, &Sweep::finished, this, &TransactionEngine::finished);
        connect(sweep, &Sweep::finished, m_core, [this, sweep] {
            if (m_sweep == sweep)
                m_sweep = nullptr;
            sweep->deleteLater();
        });
        sweep->start();
    }, Qt::QueuedConnection);
}

void TransactionEngine::stop()
{
    QMetaObject::invokeMethod(m_core, [this] {
        if (m_sweep)
            m_sweep->stop();
    }, Qt::QueuedConnection);
}

std::optional<PollReport> TransactionEngine::waitForFinished(int waitMs)
{
    QEventLoop loop;
    std::optional<PollReport> result;
    const auto connection = connect(this, &TransactionEngine::finished, &loop, [&](const PollReport &report) {
        result = report;
        loop.quit();
    });
    if (waitMs >= 0)
        QTimer::singleShot(waitMs, &loop, &QEventLoop::quit);
    loop.exec();
    disconnect(connection);
    return result;
}

void TransactionEngine::openLink()
{
    QMetaObject::invokeMethod(m_core, [core = m_core] { core->openLink(); }, Qt::QueuedConnection);
}

void TransactionEngine::closeLink()
{
    QMetaObject::invokeMethod(m_core, [core = m_core] { core->closeLink(); }, Qt::QueuedConnection);
}

} // namespace mbscope

#include "moc_transactionengine.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
