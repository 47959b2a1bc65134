#include "monitor/monitorreport.h"

#include "common/cli.h"
#include "common/transactionreport.h"

#include "protocol/hexnumber.h"
#include "capture/captureexchange.h"
#include "monitor/busmonitor.h"
#include "protocol/functioncode.h"
#include "exchange/responsematcher.h"

#include <QtCore/QJsonArray>

namespace mbscope::app {

namespace {

const char *stopName(MonitorStop stop)
{
    switch (stop) {
    case MonitorStop::Count:
        return "count";
    case MonitorStop::Duration:
        return "duration";
    case MonitorStop::Interrupted:
        return "interrupted";
    case MonitorStop::LinkLost:
        return "link_lost";
    }
    return "count";
}

QString stopText(MonitorStop stop)
{
    switch (stop) {
    case MonitorStop::Count:
        return QStringLiteral("the count was reached");
    case MonitorStop::Duration:
        return QStringLiteral("the duration was reached");
    case MonitorStop::Interrupted:
        return QStringLiteral("interrupted");
    case MonitorStop::LinkLost:
        return QStringLiteral("the link was lost");
    }
    return {};
}

} // namespace

QString MonitorReport::exchangeLine(const CaptureExchange &exchange)
{
    const Transaction &t = exchange.transaction;
    const bool unmatched = exchange.kind == CaptureExchange::Kind::UnmatchedResponse;
    const QByteArray &frame = unmatched ? t.response : t.request;
    const FrameKeys keys = ResponseMatcher::keysOf(frame, exchange.framing);
    const quint8 function = keys.functionCode & 0x7f;
    QString line = QStringLiteral("%1  unit %2  %3 %4  %5")
                       .arg(t.id, 5)
                       .arg(keys.unit, -3)
                       .arg(QStringLiteral("0x%1").arg(hexNumber(function, 2)),
                            QString::fromLatin1(functionName(function)).leftJustified(30),
                            (unmatched ? QStringLiteral("unmatched") : transactionStatusName(t.status)).leftJustified(11));
    if (!unmatched && t.latencyNs() >= 0)
        line += latencyText(t.latencyNs());
    if (!t.problem.isEmpty() && t.status != TransactionStatus::Ok)
        line += QStringLiteral("  (%1)").arg(t.problem);
    return line;
}

QString MonitorReport::text(const BusMonitor &monitor, qint64 elapsedNs, MonitorStop stop)
{
    const BusCounters &bus = monitor.bus();
    QString text = QStringLiteral("monitor       %1 (listen-only: nothing was sent)\n").arg(monitor.url().toString());
    text += QStringLiteral("stopped       after %1 s: %2\n").arg(QString::number(double(elapsedNs) / 1e9, 'f', 1), stopText(stop));
    text += QStringLiteral("bus           bytes %1  frames %2  requests %3  answers %4\n")
                .arg(monitor.bytesSeen())
                .arg(bus.frames)
                .arg(bus.requests)
                .arg(bus.responses);
    text += QStringLiteral("damaged       crc errors %1  truncated %2  malformed %3  skipped bytes %4  unmatched answers %5\n")
                .arg(bus.crcErrors)
                .arg(bus.truncated)
                .arg(bus.malformed)
                .arg(bus.skippedBytes)
                .arg(monitor.unmatchedResponses());
    text += monitor.statistics().summary();
    const QStringList problems = monitor.problems();
    for (const QString &p : problems)
        text += QStringLiteral("problem       %1\n").arg(p);
    return text;
}

QJsonObject MonitorReport::json(const BusMonitor &monitor, qint64 elapsedNs, MonitorStop stop)
{
    QJsonObject o = monitor.statistics().toJson();
    const BusCounters &bus = monitor.bus();
    o.insert(QStringLiteral("target"), monitor.url().toString());
    o.insert(QStringLiteral("elapsed_ms"), double(elapsedNs) / 1e6);
    o.insert(QStringLiteral("stopped"), QLatin1String(stopName(stop)));
    o.insert(QStringLiteral("interrupted"), stop == MonitorStop::Interrupted);
    o.insert(QStringLiteral("bus"), QJsonObject{
                                         {QStringLiteral("bytes"), double(monitor.bytesSeen())},
                                         {QStringLiteral("frames"), double(bus.frames)},
                                         {QStringLiteral("requests"), double(bus.requests)},
                                         {QStringLiteral("responses"), double(bus.responses)},
                                         {QStringLiteral("crc_errors"), double(bus.crcErrors)},
                                         {QStringLiteral("truncated"), double(bus.truncated)},
                                         {QStringLiteral("malformed"), double(bus.malformed)},
                                         {QStringLiteral("skipped_bytes"), double(bus.skippedBytes)},
                                         {QStringLiteral("skipped_runs"), double(bus.skippedRuns)},
                                         {QStringLiteral("unmatched_responses"), double(monitor.unmatchedResponses())},
                                         {QStringLiteral("late_responses"), double(monitor.pairing().lateResponses)},
                                         {QStringLiteral("silence_us"), double(monitor.silenceNs()) / 1e3},
                                     });
    o.insert(QStringLiteral("problems"), QJsonArray::fromStringList(monitor.problems()));
    o.insert(QStringLiteral("problem_count"), double(monitor.problemCount()));
    return o;
}

int MonitorReport::exitStatus(const BusMonitor &monitor)
{
    const BusCounters &bus = monitor.bus();
    if (monitor.bytesSeen() == 0)
        return ExitNothingHeard;
    if (monitor.statistics().failed() > 0 || monitor.unmatchedResponses() > 0 || bus.crcErrors > 0 || bus.truncated > 0
        || bus.malformed > 0 || bus.skippedBytes > 0)
        return ExitFailure;
    return ExitOk;
}

} // namespace mbscope::app
