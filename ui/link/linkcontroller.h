#pragma once

#include "engine/engineprogress.h"
#include "engine/pollreport.h"
#include "engine/transactionengine.h"
#include "exchange/trafficentry.h"
#include "tapsetup.h"
#include "exchange/transaction.h"
#include "traffic/capturedirectory.h"
#include "traffic/rollingcapture.h"
#include "transport/linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QObject>

#include <memory>

namespace mbscope {

class BusListener;
class TapRunner;

// Between the window's widgets and the TransactionEngine: owns the engine (and with it the engine
// thread), turns "send these bytes" and "poll these bytes" into RequestItems for the connected
// link, and reports what happened as plain signals. No widget code, so tests drive it directly
// and MainWindow only connects it to the panels.
//
// connectTo() sets the target and opens the link at once (Ready while it opens, Connected when it
// is open); a link failure puts the controller into Failed with the link's own words until the
// next request succeeds or the user connects elsewhere. A link that closed opens again with the
// next request.
class LinkController : public QObject
{
    Q_OBJECT
public:
    enum class State : quint8 {
        Disconnected,
        Ready,     // target set; the link is opening
        Connected, // the link opened and answers come back
        Failed,    // the link failed; message() says why
    };
    Q_ENUM(State)

    explicit LinkController(QObject *parent = nullptr);
    ~LinkController() override;

    void connectTo(const LinkUrl &url);
    // Listen only (the bus monitor): no engine, nothing is ever sent; every exchange another
    // master makes on the line comes out as transactionsFinished, unmatched answers as
    // framesLogged. send() and startPoll() refuse while listening.
    void listenTo(const LinkUrl &url);
    // How every engine from now on makes its links (default: Link::create); Connect opens the
    // link at once, so a stand-in link (a test's) must be named before it.
    void setLinkFactory(TransactionEngine::LinkFactory factory) { m_linkFactory = std::move(factory); }
    [[nodiscard]] bool isListening() const { return m_listener != nullptr; }
    // The inline tap (the bar's Tap): no engine; masters connect to setup.listen and their
    // requests go on to the routes' targets (TapRunner), both legs logged into this connection's
    // recording, which nothing else writes into meanwhile (trafficLog() is nullptr: the watches
    // and scans go unrecorded while the tap runs). Connected once every URL listens; a URL that
    // cannot listen leaves the controller Disconnected and says why (tapFailed). send() and
    // startPoll() refuse while tapping.
    void tapTo(const TapSetup &setup);
    [[nodiscard]] bool isTapping() const { return m_tap != nullptr; }
    [[nodiscard]] TapRunner *tap() const { return m_tap.get(); }
    void disconnectLink();
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] bool isConnected() const { return m_state != State::Disconnected; }
    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] QString message() const { return m_message; }
    // What went over the link since the last Connect (or Listen): each connection counts from zero.
    [[nodiscard]] const EngineCounters &counters() const { return m_counters; }
    // Traffic another engine had with the device (a test plan's, a replay's): the status bar's
    // requests and bytes count it too.
    void countFrames(const QList<mbscope::TrafficFrame> &frames);
    void countTransactions(const QList<mbscope::Transaction> &transactions);
    [[nodiscard]] bool isPolling() const { return m_polling; }
    [[nodiscard]] TransactionEngine *engine() const { return m_engine.get(); }

    // Sends bytes exactly as given but for an MBAP transaction id, which is the connection's next
    // (RequestItem::engineNumbered: every request on the link has an id of its own); returns the
    // transaction's number, 0 when not connected.
    quint64 send(const QByteArray &bytes);
    // Sends bytes every intervalMs (0: back to back), count times (0: until stopPoll()); each
    // MBAP request gets the connection's next transaction id.
    bool startPoll(const QByteArray &bytes, int intervalMs, quint64 count);
    // Polls bytes count times at each interval in turn (TransactionEngine::startSweep); the
    // PollReport at the end has one run per interval. stopPoll() stops it.
    bool startSweep(const QByteArray &bytes, const QList<int> &intervalsMs, quint64 count);
    void stopPoll();

    // Recording, always on unless turned off: every connection's frames are journaled into the
    // capture folder (RollingCapture) from connectTo() until the link goes. Applies from the next
    // connection.
    void setRecording(bool enabled, const CaptureDirectory &directory, const RollingCapture::Policy &policy);
    [[nodiscard]] bool isRecordingEnabled() const { return m_recordingEnabled; }
    // The journal being written, or empty (not connected, turned off, or it could not be made:
    // recordingProblem() says why).
    [[nodiscard]] QString recordingPath() const;
    [[nodiscard]] const QString &recordingProblem() const { return m_recordingProblem; }
    // Save: the journal being written moves to path and recording goes on into it; where it
    // cannot be moved (another file system), what was recorded so far is copied there instead,
    // atomically, and *copied is set. False with *error when neither could be done.
    bool keepRecordingAt(const QString &path, bool *copied, QString *error);
    // The log of the journal being written (shared: the watches' and scans' engines write into it
    // too), or nullptr. trafficLogChanged() says when it comes and goes.
    [[nodiscard]] TrafficLog *trafficLog() const { return m_capture && !m_tap ? m_capture->log() : nullptr; }

    // One line for the status bar: "Poll finished: 20 transactions, 20 ok, 0 failed; latency min
    // 1.21 ms, mean 4.05 ms, max 11.80 ms".
    [[nodiscard]] static QString describe(const PollReport &report);

Q_SIGNALS:
    void stateChanged(mbscope::LinkController::State state, const QString &message);
    // Every transaction, in batches as the engine delivers them (at most ~30 a second).
    void transactionsFinished(const QList<mbscope::Transaction> &transactions);
    // Every frame in and out as the engine logs it (TransactionEngine::framesLogged), batched as
    // the engine delivers them; link: the target's URL.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    // The newest transaction of each batch: what the decode view shows.
    void latestTransaction(const mbscope::Transaction &transaction);
    void countersChanged(const mbscope::EngineCounters &counters);
    // The engine's progress with each batch: the run of a sweep and the cycle in it.
    void progressChanged(const mbscope::EngineProgress &progress);
    void pollingChanged(bool polling);
    void pollFinished(const mbscope::PollReport &report);
    // Recording started (path), stopped (empty path), could not start (problem), or stopped on
    // its own while frames still came (the path of what came before, and the problem).
    void recordingChanged(const QString &path, const QString &problem);
    // The recording's log for other writers (the watches, the scans): a new one once a
    // connection's recording started, nullptr before it finishes. Connect directly: a receiver
    // lets go of the old log (its engines' setTrafficLog(nullptr)) before this returns.
    void trafficLogChanged(mbscope::TrafficLog *log);
    // The tap's frames of both legs, in batches (TapRunner::framesLogged): each frame's link an
    // index into links.
    void tapFramesLogged(const QList<mbscope::TrafficFrame> &frames, const QStringList &links);
    void tapCountersChanged(const mbscope::TapCounters &counters, int waiting);
    // The tap could not start (a URL that cannot listen): the controller is Disconnected.
    void tapFailed(const QString &message);

private:
    // bytes for the link, numbered by the engine.
    [[nodiscard]] RequestItem item(const QByteArray &bytes) const;
    void onTransactions(const QList<Transaction> &transactions);
    void onProgress(const EngineProgress &progress);
    void onLinkMessage(const QString &message);
    void onPollFinished(const PollReport &report);
    void setState(State state, const QString &message = {});
    void resetEngine();
    void restartCounters();
    void onObserved(const QList<Transaction> &transactions);
    void onTapFrames(const QList<TrafficFrame> &frames, const QStringList &links);
    [[nodiscard]] QString tapDescription() const;
    // The engine (or the listener) goes first (it writes into the recording's log), then the recording.
    void dropEngine();

    std::unique_ptr<TransactionEngine> m_engine;
    std::unique_ptr<BusListener> m_listener;
    std::unique_ptr<TapRunner> m_tap;
    TransactionEngine::LinkFactory m_linkFactory;
    LinkUrl m_url;
    State m_state = State::Disconnected;
    QString m_message;
    EngineCounters m_counters;
    EngineCounters m_countersBefore; // this connection's traffic not counted by its engine (a plan's, a replay's)
    bool m_polling = false;
    bool m_recordingEnabled = false;
    // A new recording into m_captures for target; its log, or nullptr with m_recordingProblem
    // saying why. recordingChanged() says which.
    TrafficLog *startRecording(const QString &target, const RollingCapture::Describe &describe = {});
    void onRecordingStopped(const QString &problem);

    CaptureDirectory m_captures;
    RollingCapture::Policy m_capturePolicy;
    std::unique_ptr<RollingCapture> m_capture;
    QString m_recordingProblem;
};

} // namespace mbscope
