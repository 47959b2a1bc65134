#include "scan/scantiming.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/progressline.h"
#include "scan/scanoptions.h"
#include "scan/scanreport.h"

#include "discovery/profiledraft.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

QString text(const TimingScanSettings &s, const TimingReport &r, JobEnd end)
{
    QString t = QStringLiteral("TIMING %1 unit %2\n\n").arg(s.url.toString()).arg(s.unit);
    t += QStringLiteral("first answer after connecting   %1 ms (%2 failed before it)\n").arg(r.firstAnswerMs).arg(r.warmupFailures);
    if (r.warmUpMs >= 0)
        t += QStringLiteral("warm-up after connecting        %1 ms (answered after waiting %1 ms, not after %2 ms)%3\n")
                 .arg(r.warmUpMs)
                 .arg(r.warmUpRefusedMs)
                 .arg(r.warmUpMs - r.warmUpRefusedMs > 10 && end != JobEnd::Completed
                          ? QStringLiteral(": not narrowed to 10 ms (%1), an upper bound").arg(end == JobEnd::Stopped ? QStringLiteral("stopped")
                                                                                                                 : QStringLiteral("time limit"))
                          : QString());
    for (const TimingReport::GapTrial &g : r.gaps)
        t += QStringLiteral("gap %1 ms%2%3 ok, %4 failed, slowest %5 ms\n")
                 .arg(g.gapMs)
                 .arg(QString(), 24 - QString::number(g.gapMs).size())
                 .arg(g.ok)
                 .arg(g.failed)
                 .arg(QString::number(double(g.maxLatencyUs) / 1000.0, 'f', 2));
    if (r.gapsHeldByWarmUp)
        t += QStringLiteral("shorter gaps                    not measured: the device hangs up after each answer and each new "
                            "connection waits its warm-up (%1 ms)\n")
                 .arg(r.pauseAfterConnectMs());
    // What a part cut short by Ctrl-C or --max-time did not measure is said so, never shown as a figure.
    const QString cut = end == JobEnd::Stopped ? QStringLiteral("stopped") : QStringLiteral("time limit");
    t += QStringLiteral("shortest gap without errors     %1\n")
             .arg(r.gapsHeldByWarmUp ? QStringLiteral("not measured (the warm-up kept every request apart)")
                  : !r.gapMeasured() ? QStringLiteral("not measured (%1 before a gap was tried through)").arg(cut)
                  : r.shortestCleanGapMs < 0 ? QStringLiteral("none of those tried (every gap had errors)")
                  : r.gapsComplete ? QStringLiteral("%1 ms").arg(r.shortestCleanGapMs)
                                   : QStringLiteral("%1 ms (shorter gaps not tried: %2)").arg(r.shortestCleanGapMs).arg(cut));
    if (r.largestQuantity == 0)
        t += QStringLiteral("largest read answered           not measured%1\n")
                 .arg(r.largestComplete ? QString() : QStringLiteral(" (%1 before it)").arg(cut));
    else
        t += QStringLiteral("largest read answered           %1%2 at address %3 (an answer PDU of %4 bytes)%5\n")
                 .arg(r.largestComplete ? QString() : QStringLiteral("at least "))
                 .arg(r.largestQuantity)
                 .arg(s.address)
                 .arg(r.largestAnswerPdu)
                 .arg(r.largestEndsMap ? QStringLiteral(": one more ran past the device's map (no exception 03), not a quantity limit")
                      : r.largestComplete ? QString()
                                          : QStringLiteral(" (%1 before the largest was found)").arg(cut));
    if (r.gapReconnects >= 0 && r.gapAnswered >= 3)
        t += QStringLiteral("connection after each answer    %1\n")
                 .arg(r.closesAfterAnswer() ? QStringLiteral("closed by the device (%1 connections for %2 answers): pipelining and "
                                                             "clients at once not measured")
                                                  .arg(r.gapReconnects)
                                                  .arg(r.gapAnswered)
                                            : QStringLiteral("kept open"));
    if (r.pipelineSent > 0)
        t += QStringLiteral("pipelined requests              %1 of %2 answered%3\n")
                 .arg(r.pipelineOk)
                 .arg(r.pipelineSent)
                 .arg(r.pipelineOk == r.pipelineSent ? QStringLiteral(": pipelining works") : QStringLiteral(": send one at a time"));
    if (r.clientsTried > 0)
        t += QStringLiteral("TCP clients served at once      %1%2\n")
                 .arg(r.clientsServed)
                 .arg(r.oldestDropped ? QStringLiteral(" (client %1 was served by closing client 1: the device knocks its oldest "
                                                       "client off, as extraClients dropOldest)")
                                            .arg(r.clientsTried)
                      : r.clientsServed == s.maxClients ? QStringLiteral(" (all tried; there may be room for more)")
                                                        : QStringLiteral(" (client %1 was not served)").arg(r.clientsTried));
    if (end == JobEnd::Stopped)
        t += QStringLiteral("\nstopped (Ctrl-C): later measurements were not made\n");
    else if (end == JobEnd::TimeLimit)
        t += QStringLiteral("\ntime limit (--max-time %1) reached: later measurements were not made\n")
                 .arg(ScanReport::durationText(s.maxDurationMs));
    const int gap = r.recommendedGapMs();
    const int timeout = r.recommendedTimeoutMs();
    // Only what was measured becomes a setting: without a gap measured, none is recommended.
    const bool gapKnown = r.gapMeasured();
    t += gapKnown ? QStringLiteral("\nSettings (twice the shortest clean gap, three times the slowest answer):\n")
                  : QStringLiteral("\nSettings (three times the slowest answer; no gap was measured, so none is given):\n");
    t += QStringLiteral("  mbscope watch link:    %1\"timeoutMs\": %2%3\n")
             .arg(gapKnown ? QStringLiteral("\"gapMs\": %1, ").arg(gap) : QString())
             .arg(timeout)
             .arg(r.pauseAfterConnectMs() > 0 ? QStringLiteral(", \"warmUpMs\": %1").arg(r.pauseAfterConnectMs()) : QString());
    t += QStringLiteral("  mbscope poll/read:     --timeout %1ms\n").arg(timeout);
    t += QStringLiteral("  Telegraf inputs.modbus: timeout = \"%1ms\"\n").arg(timeout);
    QStringList workarounds;
    if (gapKnown)
        workarounds.append(QStringLiteral("pause_between_requests = \"%1ms\"").arg(gap));
    workarounds.append(QStringLiteral("pause_after_connect = \"%1ms\"").arg(r.pauseAfterConnectMs()));
    t += QStringLiteral("    [inputs.modbus.workarounds] %1\n").arg(workarounds.join(QStringLiteral(", ")));
    return t;
}

QJsonObject json(const TimingScanSettings &s, const TimingReport &r, JobEnd end)
{
    QJsonArray gaps;
    for (const TimingReport::GapTrial &g : r.gaps)
        gaps.append(QJsonObject{{QStringLiteral("gap_ms"), g.gapMs},
                                {QStringLiteral("ok"), g.ok},
                                {QStringLiteral("failed"), g.failed},
                                {QStringLiteral("max_latency_ms"), double(g.maxLatencyUs) / 1000.0}});
    return QJsonObject{
        {QStringLiteral("target"), s.url.toString()},
        {QStringLiteral("unit"), int(s.unit)},
        {QStringLiteral("first_answer_ms"), double(r.firstAnswerMs)},
        {QStringLiteral("warmup_failures"), r.warmupFailures},
        {QStringLiteral("warm_up_ms"), r.warmUpMs >= 0 ? QJsonValue(double(r.warmUpMs)) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("warm_up_refused_ms"), r.warmUpMs >= 0 ? QJsonValue(double(r.warmUpRefusedMs)) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("gaps"), gaps},
        {QStringLiteral("shortest_clean_gap_ms"), r.gapsHeldByWarmUp || !r.gapMeasured() ? QJsonValue(QJsonValue::Null)
                                                                                          : QJsonValue(r.shortestCleanGapMs)},
        {QStringLiteral("gaps_held_by_warm_up"), r.gapsHeldByWarmUp},
        {QStringLiteral("gaps_complete"), r.gapsComplete},
        {QStringLiteral("largest_quantity"), r.largestQuantity == 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(r.largestQuantity)},
        {QStringLiteral("largest_complete"), r.largestComplete},
        {QStringLiteral("largest_answer_pdu"), r.largestQuantity == 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(r.largestAnswerPdu)},
        {QStringLiteral("largest_ends_map"), r.largestEndsMap},
        {QStringLiteral("closes_after_answer"), r.gapReconnects >= 0 && r.gapAnswered >= 3 ? QJsonValue(r.closesAfterAnswer())
                                                                                             : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("pipeline_sent"), r.pipelineSent},
        {QStringLiteral("pipeline_ok"), r.pipelineSent == 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(r.pipelineOk)}, // null: not tried
        {QStringLiteral("clients_tried"), r.clientsTried},
        {QStringLiteral("clients_served"), r.clientsTried == 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(r.clientsServed)}, // null: not tried
        {QStringLiteral("clients_extra"), r.clientsTried == 0 ? QStringLiteral("not measured")
                                          : r.clientsServed == r.clientsTried
                                              ? QStringLiteral("not reached")
                                              : (r.oldestDropped ? QStringLiteral("drop_oldest") : QStringLiteral("refuse"))},
        {QStringLiteral("stopped"), end == JobEnd::Stopped},
        {QStringLiteral("end"), QString::fromLatin1(jobEndName(end))},
        {QStringLiteral("recommended"),
         QJsonObject{{QStringLiteral("gap_ms"), r.gapMeasured() ? QJsonValue(r.recommendedGapMs()) : QJsonValue(QJsonValue::Null)},
                     {QStringLiteral("timeout_ms"), r.recommendedTimeoutMs()},
                     {QStringLiteral("telegraf_pause_between_requests"),
                      r.gapMeasured() ? QJsonValue(QStringLiteral("%1ms").arg(r.recommendedGapMs())) : QJsonValue(QJsonValue::Null)},
                     {QStringLiteral("telegraf_pause_after_connect"),
                      QStringLiteral("%1ms").arg(r.pauseAfterConnectMs())}}},
    };
}

// The limits measured merged into the profile at path.
bool writeLimits(const QString &path, const TimingReport &report, quint8 function, QTextStream &err)
{
    return mergeIntoProfileFile(path, [&](const QByteArray &profile, QString *said, QString *problem) {
        const QByteArray merged = ProfileDraft::mergeLimits(profile, report.profileLimits(function), report.answeredReads(function), said,
                                                            problem);
        *said = QStringLiteral("limits measured: ") + *said;
        return merged;
    }, "profile limits", err);
}

} // namespace

int runTimingScan(const TimingScanSettings &settings, bool asJson, const ScanRecord &record, const QString &profilePath,
                  QTextStream &out, QTextStream &err)
{
    if (const QString problem = settings.problem(); !problem.isEmpty()) {
        err << "mbscope scan: " << problem << '\n';
        return ExitUsage;
    }
    TrafficRecording recording;
    if (!openRecording(recording, record.settings, record.metadata, QStringLiteral("scan"), err))
        return ExitUsage;
    recording.log()->setShared(true); // the pipelined burst and every client on engines of their own
    FrameLog frames;
    if (!openFrameLog(frames, record.print, QStringLiteral("scan"), err))
        return ExitUsage;
    TimingScanner scanner;
    if (recording.isOpen())
        scanner.setTrafficLog(recording.log());
    scanner.setFramesPublished(frames.isOpen());
    QObject::connect(&scanner, &TimingScanner::framesLogged, &frames, &FrameLog::addFrames);
    InterruptWatcher interrupts;
    ProgressLine line;
    frames.setProgressLine(&line);
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &scanner, &TimingScanner::stop);
    QString part; // what is being measured: "gap 50 ms"
    QObject::connect(&scanner, &TimingScanner::step, &scanner, [&](const QString &what) { part = what; });
    QObject::connect(&scanner, &TimingScanner::progressChanged, &scanner,
                     [&](const JobProgress &p) { line.show(ScanReport::progressText(QStringLiteral("steps"), p, part)); });
    const std::optional<TimingReport> report = scanner.run(settings);
    line.clear();
    scanner.setTrafficLog(nullptr); // the last frames reach the journal
    finishRecording(recording, err);
    if (!report)
        return ExitUsage;
    if (report->firstAnswerMs < 0) {
        if (scanner.end() == JobEnd::TimeLimit)
            err << "mbscope scan: the time limit (" << ScanReport::durationText(settings.maxDurationMs) << ") came before unit "
                << settings.unit << " at " << settings.url.toString() << " answered: nothing to time\n";
        else if (scanner.end() == JobEnd::Stopped)
            err << "mbscope scan: stopped before unit " << settings.unit << " at " << settings.url.toString()
                << " answered: nothing to time\n";
        else
            err << "mbscope scan: unit " << settings.unit << " at " << settings.url.toString() << " never answered within "
                << settings.warmupLimitMs << " ms: nothing to time\n";
        if (!asJson)
            return ExitFailure;
    }
    if (!profilePath.isEmpty() && report->firstAnswerMs >= 0 && !writeLimits(profilePath, *report, settings.function, err))
        return ExitUsage;
    if (asJson)
        out << QJsonDocument(json(settings, *report, scanner.end())).toJson(QJsonDocument::Indented);
    else
        out << text(settings, *report, scanner.end());
    out.flush();
    return report->firstAnswerMs < 0 ? ExitFailure : ExitOk;
}

} // namespace mbscope::app
