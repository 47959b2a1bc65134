#pragma once

#include "tapsetup.h"

#include "exchange/trafficentry.h"
#include "tap/tapsettings.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QStringList>

#include <memory>

class QThread;

namespace mbscope {

class FaultInjector;
class Simulator;
class TapForwarder;
class TrafficLog;

// The window's inline tap (the connection bar's Tap): core/tap's TapForwarder behind a Simulator
// without units (its endpoints take the masters' requests and hand them to the forwarder, as in
// `mbscope tap`), on a thread of its own, so that forwarding never waits for painting and the
// device leg's latency is the device's, not the GUI's backlog.
//
// Both legs go into one traffic log: the window's recording (its journal: the master leg as the
// tap's endpoints saw it, the device leg as its engines did, as `mbscope tap --record` writes
// it), or a log of the runner's own when recording is off. Only the tap's thread writes into it.
// At most every 33 ms the tap's thread copies what was logged since and hands it over
// (framesLogged): the master leg as its masters saw it (a request out of the master, the tap's
// answer in, an empty frame in for one it left unanswered), as analyze reads a server's
// journal, so that the traffic list pairs and times both legs alike.
//
//     TapRunner tap(setup);
//     if (!tap.listen(&error)) ...;          // binds (port 0: any free port): tap.endpoints()
//     tap.start(recording ? recording->log() : nullptr);
//     ...
//     tap.stop();                              // the last frames come out of stop() itself
class TapRunner : public QObject
{
    Q_OBJECT
public:
    explicit TapRunner(const TapSetup &setup, QObject *parent = nullptr);
    ~TapRunner() override; // stop()

    // Binds every listen URL, in the owner's thread; false with *error naming the URL at fault.
    bool listen(QString *error);
    // The endpoints as bound ("tcp://127.0.0.1:40321"): where masters connect.
    [[nodiscard]] QStringList endpoints() const { return m_endpoints; }
    [[nodiscard]] const TapSetup &setup() const { return m_setup; }

    // log: where both legs are logged (the window's recording; not owned, must outlive stop()),
    // or nullptr for a log of the runner's own. Nothing else may write into it while the tap runs.
    void start(TrafficLog *log);
    // Closes the endpoints and the targets' links, ends the thread; the frames logged since the
    // last batch come out before it returns.
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }

    // Where the link names of framesLogged() stand for the masters' leg.
    [[nodiscard]] bool isMasterLink(const QString &link) const { return m_endpoints.contains(link); }

Q_SIGNALS:
    // Frames in log order, each frame's link an index into links (the log's link names: the
    // listening endpoints' URLs for the master leg, the targets' for the device leg).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QStringList &links);
    // With each batch: what the tap has done since it started, and the requests waiting for a device.
    void countersChanged(const mbscope::TapCounters &counters, int waiting);
    // A target's link opened, or failed or closed with requests in flight (its words).
    void targetOpened(const QString &target);
    void targetMessage(const QString &target, const QString &message);

private:
    // In the tap's thread: what was logged since the last call, the master leg turned round.
    [[nodiscard]] QList<TrafficFrame> takeFrames(QStringList *links);
    void publish(); // in the tap's thread, on the batch timer

    TapSetup m_setup;
    QThread *m_thread = nullptr;
    QObject *m_anchor = nullptr;      // lives in m_thread: the batch timer's parent
    Simulator *m_simulator = nullptr; // lives in m_thread once started
    TapForwarder *m_forwarder = nullptr;
    std::unique_ptr<FaultInjector> m_injector; // the setup's fault rules; outlives the simulator
    std::unique_ptr<TrafficLog> m_ownLog; // when the window does not record
    TrafficLog *m_log = nullptr;
    quint64 m_next = 0; // the sequence of the first frame not handed over yet
    QStringList m_endpoints;
    bool m_running = false;
};

} // namespace mbscope
