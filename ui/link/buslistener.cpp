#include "buslistener.h"

#include "capture/captureexchange.h"
#include "monitor/busmonitor.h"

#include <QtCore/QThread>

namespace mbscope {

BusListener::BusListener(const LinkUrl &url, TrafficLog *log, QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<mbscope::CaptureExchange>();
    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("mbscope bus monitor"));
    m_monitor = new BusMonitor(url, BusMonitor::Options{});
    if (log)
        m_monitor->setTrafficLog(log);
    m_monitor->moveToThread(m_thread);
    connect(m_monitor, &BusMonitor::opened, this, &BusListener::opened);
    connect(m_monitor, &BusMonitor::linkFailed, this, &BusListener::failed);
    connect(m_monitor, &BusMonitor::exchangeObserved, this, &BusListener::onExchange);
    m_flush.setInterval(33);
    m_flush.setSingleShot(true);
    connect(&m_flush, &QTimer::timeout, this, &BusListener::flush);
}

BusListener::~BusListener()
{
    if (m_thread->isRunning()) {
        BusMonitor *monitor = m_monitor;
        QMetaObject::invokeMethod(
            monitor,
            [monitor] {
                monitor->stop();
                delete monitor;
            },
            Qt::BlockingQueuedConnection);
        m_thread->quit();
        m_thread->wait();
    } else {
        delete m_monitor;
    }
}

void BusListener::start()
{
    m_thread->start();
    QMetaObject::invokeMethod(m_monitor, &BusMonitor::start, Qt::QueuedConnection);
}

void BusListener::onExchange(const CaptureExchange &exchange)
{
    if (exchange.kind == CaptureExchange::Kind::UnmatchedResponse) {
        TrafficFrame frame;
        frame.tNs = exchange.transaction.firstByteNs;
        frame.direction = TrafficDirection::In;
        frame.verdict = TrafficVerdict::Unsolicited;
        frame.bytes = exchange.transaction.response;
        m_unmatched.append(frame);
    } else {
        m_transactions.append(exchange.transaction);
    }
    if (!m_flush.isActive())
        m_flush.start();
}

void BusListener::flush()
{
    if (!m_transactions.isEmpty())
        Q_EMIT transactionsObserved(std::exchange(m_transactions, {}));
    if (!m_unmatched.isEmpty())
        Q_EMIT unmatchedObserved(std::exchange(m_unmatched, {}));
}

} // namespace mbscope
