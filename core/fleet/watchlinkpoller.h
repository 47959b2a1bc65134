#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"
#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevaluator.h"
#include "watch/watchruleevent.h"

#include "exchange/requestitem.h"
#include "exchange/trafficentry.h"
#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <deque>
#include <memory>

namespace mbscope {

class TrafficLog;
class TransactionEngine;

// The watches of one link, polled by one engine (its own thread), one request at a time: a
// serial bus is half-duplex, and a gateway or device serves one master's question at a time.
// The watch due first goes next (ties in the session's order), each at its own interval, start
// to start; after each exchange the line is left idle for gapMs. A timeout costs only that turn.
// After a link error no request is sent for a backoff that doubles from reconnectMinMs to
// reconnectMaxMs, then the link is opened again; a link that opens again counts a reconnect, and
// an attempt that fails counts a failed poll (a link error) of each of the link's watches.
// Lives in the runner's thread (WatchFleet), never the GUI's.
class WatchLinkPoller : public QObject
{
    Q_OBJECT
public:
    struct Watch {
        int index = -1; // in SessionWatches::watches
        WatchDefinition definition;
    };

    WatchLinkPoller(const WatchLinkSettings &settings, const QList<Watch> &watches, QObject *parent = nullptr);
    ~WatchLinkPoller() override;

    void start();
    void stop();
    // Where the engine's frames go (WatchFleet::setTrafficLog), now and from the next start().
    void setTrafficLog(TrafficLog *log);
    // framesLogged() on or off, from the next start().
    void setFramesPublished(bool published) { m_framesPublished = published; }
    // Queues a write to go before the next poll; writeFinished() says how it went.
    void write(quint64 id, int watch, quint16 address, const QList<quint16> &words);

Q_SIGNALS:
    void sampled(const mbscope::WatchSample &sample, const mbscope::WatchCounters &counters);
    void ruleChanged(const mbscope::WatchRuleEvent &event);
    void linkStateChanged(const mbscope::WatchLinkState &state);
    void writeFinished(quint64 id, int watch, quint16 address, bool ok, const QString &message);
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

private:
    struct Entry {
        Watch watch;
        QByteArray pdu;
        qint64 dueNs = 0;
        quint64 polls = 0;
        WatchRuleEvaluator rules;
        WatchCounters counters;
    };
    struct PendingWrite {
        quint64 id = 0;
        int watch = -1;
        quint16 address = 0;
        QByteArray pdu;
        quint8 unit = 1;
    };
    enum class Phase : quint8 { Idle, Busy, Backoff, Connecting, Stopped };

    void pump();
    void armTimer(qint64 waitNs);
    void onTimer();
    void onTransactions(const QList<Transaction> &transactions);
    void onLinkOpened();
    void onLinkMessage(const QString &message);
    void finishPoll(const Transaction &t);
    void finishWrite(const Transaction &t);
    void linkLost(const QString &message);
    void failOpen(const QString &message);
    void setState(WatchLinkState::State state, const QString &message = {}, int retryInMs = 0);
    [[nodiscard]] RequestItem requestFor(const QByteArray &pdu, quint8 unit);
    [[nodiscard]] int nextEntry() const;

    WatchLinkSettings m_settings;
    std::optional<LinkUrl> m_url;
    QString m_urlError;
    QList<Entry> m_entries;
    std::deque<PendingWrite> m_writes;
    std::unique_ptr<TransactionEngine> m_engine;
    TrafficLog *m_log = nullptr;
    bool m_framesPublished = false;
    QTimer m_timer;
    Phase m_phase = Phase::Stopped;
    quint64 m_inFlight = 0;      // engine id of the request in flight
    int m_inFlightEntry = -1;    // its entry (-1: a write)
    PendingWrite m_inFlightWrite;
    quint16 m_transactionId = 0;
    int m_backoffMs = 0;
    quint64 m_opens = 0;
    WatchLinkState m_state;
};

} // namespace mbscope
