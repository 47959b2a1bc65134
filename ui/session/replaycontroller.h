#pragma once

#include "sessionmetatypes.h"
#include "capture/captureoptions.h"
#include "exchange/statistics.h"
#include "exchange/transaction.h"
#include "replay/replayoutcome.h"
#include "replay/replayresponder.h"
#include "replay/replayresult.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QString>

#include <memory>
#include <optional>

class QThread;

namespace mbscope {

class LinkController;
class ReplayDifferencesModel;
class ReplayScript;
class ReplayServer;
class ReplayWorker;

// Replay in the window, three ways, over the core's replay classes (what `mbscope analyze` and
// `mbscope replay` run). No widgets: ReplayPanel shows it, tests drive it directly.
//  - Offline: openSource() reads a capture (pcap, pcapng), a traffic journal or a session
//    document's capture in a thread, pairs requests with answers as analyze does, and hands its
//    transactions to whoever listens (captureAnalysed: the traffic monitor, an analysis panel).
//  - Against the live target: startReplay() re-sends the opened source's recorded requests to
//    the LinkController's target at the recorded pacing or a chosen speed, in a thread of its
//    own (ReplayWorker), and lists each answer against the recorded one (differences()).
//  - As the device: startServing() answers with the recorded answers on an endpoint
//    (ReplayServer).
class ReplayController : public QObject
{
    Q_OBJECT
public:
    explicit ReplayController(LinkController *link, QObject *parent = nullptr);
    ~ReplayController() override;

    // Which ports carry Modbus in a capture, and the timeout that pairs it (the next open).
    void setCaptureOptions(const CaptureOptions &options) { m_options = options; }
    [[nodiscard]] const CaptureOptions &captureOptions() const { return m_options; }

    // Starts reading source; false (and sourceFailed) when it cannot start: a read or a replay
    // running, no such file, a session without a capture. The result comes with sourceOpened
    // and captureAnalysed, or sourceFailed.
    bool openSource(const QString &source);
    [[nodiscard]] bool isLoading() const { return m_loading != nullptr; }
    [[nodiscard]] bool hasSource() const { return m_script != nullptr; }
    [[nodiscard]] QString sourcePath() const { return m_source; }
    // The source's file name: what panels and plots are titled with.
    [[nodiscard]] QString sourceTitle() const { return m_title; }
    [[nodiscard]] std::shared_ptr<const ReplayScript> script() const { return m_script; }
    // The transactions read (every request with its outcome, in request order).
    [[nodiscard]] qsizetype transactionCount() const { return m_transactionCount; }
    [[nodiscard]] const Statistics &sourceStatistics() const { return m_statistics; }
    // "bench.pcapng (pcapng): 150 transactions, 148 ok, 2 failed; latency median 4.012 ms, p95 7.901 ms"
    [[nodiscard]] QString sourceSummary() const { return m_summary; }

    // Replays the opened source to the connected target (speed 1: as recorded, N: N times
    // faster, 0: back to back). The recording's writes are sent only when sendWrites (the
    // panel asks first); otherwise each is skipped and listed in lastResult()->skippedWrites and
    // the summary. False with *error when it cannot start (nothing opened, not connected, the
    // link polling, a replay already running). The link's own connection is closed first, so a
    // serial port or a device server that takes one client is free.
    bool startReplay(double speed, bool sendWrites, QString *error);
    void stopReplay();
    [[nodiscard]] bool isReplaying() const { return m_worker != nullptr; }
    [[nodiscard]] ReplayDifferencesModel *differences() const { return m_differences; }
    [[nodiscard]] const std::optional<ReplayResult> &lastResult() const { return m_lastResult; }
    // The counts and the latency line of the last replay, or why it ended.
    [[nodiscard]] QString replaySummary() const { return m_replaySummary; }

    // Serves the opened source's answers on url; false with *error.
    bool startServing(const QString &url, ReplayResponder::Unrecorded unrecorded, double speed, QString *error);
    void stopServing();
    [[nodiscard]] ReplayServer *server() const { return m_server; }
    // "Serving 12 recorded answers (3 distinct requests) on tcp://127.0.0.1:1502: 4 served, ..."
    [[nodiscard]] QString servingText() const;

Q_SIGNALS:
    // An opened capture re-analysed offline: its transactions (for the traffic monitor and the
    // analysis panels), titled with the capture's file name.
    void captureAnalysed(const QString &title, const QList<mbscope::Transaction> &transactions);
    void sourceOpened(const QString &summary);
    void sourceFailed(const QString &message);
    void busyChanged();
    void replayStarted();
    // Each replayed request as its answer came (its transaction also for the traffic monitor).
    void outcomeReplayed(const mbscope::ReplayOutcome &outcome);
    void transactionsReplayed(const QList<mbscope::Transaction> &transactions);
    void replayFinished(const QString &summary);

private:
    struct Loaded;
    void onLoaded(const std::shared_ptr<Loaded> &loaded);
    void onOutcome(const ReplayOutcome &outcome);
    void onReplayFinished(const ReplayResult &result, const QString &linkProblem);

    LinkController *m_link;
    CaptureOptions m_options;
    QThread *m_loading = nullptr;
    QString m_source;
    QString m_title;
    std::shared_ptr<const ReplayScript> m_script;
    qsizetype m_transactionCount = 0;
    Statistics m_statistics;
    QString m_summary;

    QThread *m_replayThread = nullptr;
    ReplayWorker *m_worker = nullptr;
    ReplayDifferencesModel *m_differences;
    std::optional<ReplayResult> m_lastResult;
    QString m_replaySummary;
    ReplayServer *m_server;
};

} // namespace mbscope
