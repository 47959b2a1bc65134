#pragma once

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QTimer>

class QThread;

namespace mbscope {

class BusMonitor;
class TrafficLog;
struct CaptureExchange;

// The window's listen-only link: a BusMonitor on a thread of its own (the window's thread never
// sits on the receive path), its exchanges handed over as the engine hands its transactions, in
// batches at most ~30 a second, so that the traffic list and the Analysis dock take them alike.
class BusListener : public QObject
{
    Q_OBJECT
public:
    // log: where every frame seen goes (the window's recording), or nullptr; used by the
    // monitor's thread only from start() on.
    BusListener(const LinkUrl &url, TrafficLog *log, QObject *parent = nullptr);
    ~BusListener() override; // stops the monitor and its thread

    void start();

Q_SIGNALS:
    void opened();
    void failed(const QString &message);
    void transactionsObserved(const QList<mbscope::Transaction> &transactions);
    void unmatchedObserved(const QList<mbscope::TrafficFrame> &frames);

private:
    void onExchange(const CaptureExchange &exchange);
    void flush();

    QThread *m_thread = nullptr;
    BusMonitor *m_monitor = nullptr;
    QList<Transaction> m_transactions;
    QList<TrafficFrame> m_unmatched;
    QTimer m_flush;
};

} // namespace mbscope
