#include "probechannel.h"

#include "engine/transactionengine.h"
#include "exchange/requestitem.h"
#include "exchange/trafficentry.h"
#include "protocol/adubuilder.h"

#include <QtCore/QEventLoop>
#include <QtCore/QThread>
#include <QtCore/QTimer>

namespace mbscope {

ProbeChannel::ProbeChannel(QObject *parent)
    : QObject(parent)
    , m_engine(new TransactionEngine(this))
{
    m_engine->setFramesPublished(true);
    connect(m_engine, &TransactionEngine::transactionsFinished, this, &ProbeChannel::onTransactions);
    connect(m_engine, &TransactionEngine::linkOpened, this, &ProbeChannel::linkOpened);
    connect(m_engine, &TransactionEngine::framesLogged, this,
            [this](const QList<TrafficFrame> &frames, const QString &link) {
                onFrames(frames);
                Q_EMIT framesLogged(frames, link);
            });
}

ProbeChannel::~ProbeChannel() = default;

void ProbeChannel::setTarget(const LinkUrl &url)
{
    m_url = url;
    // One request at a time, each waiting for the last: the batches of finished transactions must
    // not wait out the engine's usual 33 ms (a 247-id scan would spend 8 s in it).
    EngineOptions options;
    options.batchIntervalMs = 1;
    options.warmUp = std::chrono::milliseconds(m_warmUpMs);
    m_engine->setTarget(url, options);
}

void ProbeChannel::setWarmUpMs(int warmUpMs)
{
    m_warmUpMs = warmUpMs;
    setTarget(m_url);
}

void ProbeChannel::setTrafficLog(TrafficLog *log)
{
    // From the thread that shows the scan while the channel lives in a job's thread (JobThread):
    // set there, between two of its steps.
    if (thread() != QThread::currentThread() && thread()->isRunning()) {
        QMetaObject::invokeMethod(this, [this, log] { m_engine->setTrafficLog(log); }, Qt::BlockingQueuedConnection);
        return;
    }
    m_engine->setTrafficLog(log);
}

void ProbeChannel::setLinkFactory(const LinkFactory &factory)
{
    m_engine->setLinkFactory(factory);
}

QByteArray ProbeChannel::frame(quint8 unit, const QByteArray &pdu)
{
    AduOptions options;
    options.framing = m_url.framing();
    options.unitId = unit;
    options.transactionId = ++m_transactionId;
    return AduBuilder::complete(pdu, options);
}

bool ProbeChannel::probe(quint8 unit, const QByteArray &pdu, int timeoutMs)
{
    return probeRaw(frame(unit, pdu), timeoutMs);
}

bool ProbeChannel::probeRaw(const QByteArray &adu, int timeoutMs)
{
    if (isBusy())
        return false;
    m_nextAdu = adu;
    m_nextTimeoutMs = timeoutMs;
    m_waiting = true;
    const qint64 left = m_sinceEnd.isValid() ? m_gapMs - m_sinceEnd.elapsed() : 0;
    const quint64 generation = m_generation;
    QTimer::singleShot(int(qMax<qint64>(0, left)), this, [this, generation] {
        if (generation == m_generation)
            sendNow();
    });
    return true;
}

void ProbeChannel::sendNow()
{
    m_waiting = false;
    RequestItem item = RequestItem::forLink(m_nextAdu, m_url);
    item.timeoutMs = m_nextTimeoutMs;
    item.retries = 0;
    m_bytesRead.clear();
    m_haveDone = false;
    m_pendingId = m_engine->send(item);
}

void ProbeChannel::onFrames(const QList<TrafficFrame> &frames)
{
    if (m_pendingId == 0)
        return;
    for (const TrafficFrame &f : frames) {
        if (f.direction == TrafficDirection::In)
            m_bytesRead += f.bytes;
    }
}

void ProbeChannel::onTransactions(const QList<Transaction> &transactions)
{
    if (m_pendingId == 0 || m_haveDone)
        return;
    for (const Transaction &t : transactions) {
        if (t.id != m_pendingId || t.status == TransactionStatus::Late)
            continue;
        m_done = t;
        m_haveDone = true;
        // The frames of this batch follow the transactions in a signal of their own: let them in first.
        const quint64 generation = m_generation;
        QTimer::singleShot(0, this, [this, generation] {
            if (generation == m_generation)
                deliver();
        });
        return;
    }
}

void ProbeChannel::deliver()
{
    m_engine->deliverPending();
    const Transaction done = m_done;
    const QByteArray bytes = m_bytesRead;
    m_pendingId = 0;
    m_haveDone = false;
    m_sinceEnd.start();
    Q_EMIT answered(done, bytes);
}

std::optional<ProbeChannel::Answer> ProbeChannel::ask(quint8 unit, const QByteArray &pdu, int timeoutMs)
{
    if (!probe(unit, pdu, timeoutMs))
        return std::nullopt;
    return waitForAnswer();
}

std::optional<ProbeChannel::Answer> ProbeChannel::askRaw(const QByteArray &adu, int timeoutMs)
{
    if (!probeRaw(adu, timeoutMs))
        return std::nullopt;
    return waitForAnswer();
}

std::optional<ProbeChannel::Answer> ProbeChannel::waitForAnswer()
{
    QEventLoop loop;
    std::optional<Answer> result;
    const QMetaObject::Connection done = connect(this, &ProbeChannel::answered, &loop,
                                                 [&](const Transaction &t, const QByteArray &bytes) {
                                                     result = Answer{t, bytes};
                                                     loop.quit();
                                                 });
    const QMetaObject::Connection gone = connect(this, &ProbeChannel::cancelled, &loop, &QEventLoop::quit);
    loop.exec();
    disconnect(done);
    disconnect(gone);
    return result;
}

void ProbeChannel::cancel()
{
    const bool busy = isBusy();
    ++m_generation;
    m_pendingId = 0;
    m_waiting = false;
    m_haveDone = false;
    m_engine->closeLink();
    if (busy)
        Q_EMIT cancelled();
}

void ProbeChannel::closeLink()
{
    m_engine->closeLink();
}

} // namespace mbscope

#include "moc_probechannel.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
