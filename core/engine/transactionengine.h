#pragma once

#include "engineoptions.h"
#include "engineprogress.h"
#include "pollreport.h"
#include "pollsettings.h"
#include "exchange/requestitem.h"
#include "exchange/trafficentry.h"
#include "exchange/transaction.h"

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QThread>

#include <functional>
#include <optional>

namespace mbscope {

class EngineCore;
class Link;
class Sweep;
class TrafficLog;

// Sends requests and measures answers on a thread of its own, which it creates and owns with the
// link inside it. Every public method is thread-safe: it posts the work to the engine thread and
// returns at once. Observers only receive: batches of finished transactions and a progress
// snapshot at most ~30 times a second (EngineOptions::batchIntervalMs), and finished() with the
// statistics when a poll or sweep ends. Nothing on the receive path waits for them.
//
// Headless use (the engine needs an event loop in the calling thread to deliver its signals):
//   TransactionEngine engine;
//   engine.setTarget(url);
//   std::optional<Transaction> t = engine.sendAndWait(RequestItem::forLink(bytes, url));
// or for a poll: connect finished(), startPoll(settings), run the event loop (or waitForFinished()).
class TransactionEngine : public QObject
{
    Q_OBJECT
public:
    using LinkFactory = std::function<Link *(const LinkUrl &url, QObject *parent)>;

    explicit TransactionEngine(QObject *parent = nullptr);
    ~TransactionEngine() override;

    // Makes the links (default: Link::create). Called in the engine thread; for tests.
    void setLinkFactory(LinkFactory factory);
    // The device to talk to. The link opens on the first request and again on the next request
    // after it closed.
    void setTarget(const LinkUrl &url, const EngineOptions &options = {});
    // Every frame in and out and every transaction go to the log; it is used from the engine
    // thread from now on (until setTrafficLog(nullptr) returns), so it must outlive that.
    void setTrafficLog(TrafficLog *log);
    // framesLogged() batches on or off (off by default).
    void setFramesPublished(bool published);
    // Emits the batches waiting in the engine thread now (transactions, frames, progress) and
    // delivers them to receivers in the calling thread before it returns: for a caller that is
    // about to stop listening (waits for the engine thread).
    void deliverPending();
    // Writes the traffic log's pending journal batch now (waits for the engine thread).
    void flushTrafficLog();

    // Queues one request; returns the id its Transaction will carry (Transaction::id).
    quint64 send(const RequestItem &item);
    // Sends and waits, running a local event loop, until the transaction is recorded or waitMs
    // passes (-1: the request's timeouts and retries, plus the connect timeout, plus a margin).
    // Call it from the thread that owns the engine.
    [[nodiscard]] std::optional<Transaction> sendAndWait(const RequestItem &item, int waitMs = -1);

    // Starts a poll or a sweep (stopping one that runs: its finished() comes first).
    void startPoll(const PollSettings &settings);
    void startSweep(const SweepSettings &settings);
    // Stops a poll or sweep promptly: requests in flight are abandoned, finished() still
    // delivers the statistics so far. Safe to call from any thread (a Ctrl-C handler's event).
    void stop();
    // Runs a local event loop until finished() (or waitMs, -1: no limit); returns the report.
    [[nodiscard]] std::optional<PollReport> waitForFinished(int waitMs = -1);
    // Closes the link now; requests in flight end as link errors.
    void closeLink();
    // Opens the link now rather than with the first request: linkOpened() when it is open,
    // linkMessage() with the link's words when it cannot be.
    void openLink();

Q_SIGNALS:
    void transactionsFinished(const QList<mbscope::Transaction> &transactions);
    // With setFramesPublished(true): every frame in and out as the traffic log holds it, with
    // the engine's verdicts and transaction ids (which pair an answer with its request), batched
    // with the transactions, just after them; link: the target's URL (EngineRecorder::framesLogged).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void progress(const mbscope::EngineProgress &progress);
    void finished(const mbscope::PollReport &report);
    // What the link said when it failed or closed with requests in flight.
    void linkMessage(const QString &message);
    void linkOpened();

private:
    void startRuns(const SweepSettings &settings, bool isSweep);

    QThread m_thread;
    EngineCore *m_core;       // lives in m_thread
    Sweep *m_sweep = nullptr; // engine thread only
    LinkUrl m_url;            // caller's thread: for sendAndWait's default wait
    qint64 m_paceWaitMs = 0;  // caller's thread: the longest the device's pace (gap, warm-up) holds a request
};

} // namespace mbscope
