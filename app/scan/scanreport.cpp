#include "scan/scanreport.h"

#include "common/transactionreport.h"

#include "protocol/hextext.h"

#include <QtCore/QJsonArray>

namespace mbscope::app {

namespace {

QString hex2(int v)
{
    return QStringLiteral("%1").arg(v, 2, 16, QLatin1Char('0')).toUpper();
}

// The ids of first-last that are no unit address: the unit addresses are 1-247; 0 is the
// broadcast and 248-255 are reserved (Serial Line V1.02, 2.2). An MBAP server or gateway may
// still answer them (--all-ids asks them on tcp, tls and udp only).
QStringList outsideUnitAddresses(int first, int last)
{
    QStringList outside;
    if (first == 0)
        outside.append(QStringLiteral("0"));
    const int from = qMax(first, 248);
    if (last >= from)
        outside.append(from == last ? QString::number(from) : QStringLiteral("%1-%2").arg(from).arg(last));
    return outside;
}

// "0-255: 247 unit addresses (1-247) and 9 ids outside them (0, 248-255)", or "1-247".
QString unitRangeText(int first, int last)
{
    const QString range = QStringLiteral("%1-%2").arg(first).arg(last);
    const QStringList outside = outsideUnitAddresses(first, last);
    if (outside.isEmpty())
        return range;
    const int inside = qMax(0, qMin(last, 247) - qMax(first, 1) + 1);
    const int others = (last - first + 1) - inside;
    return QStringLiteral("%1: %2 unit %3 (1-247) and %4 %5 outside them (%6: no unit address on a serial line; an MBAP "
                          "server or gateway may answer)")
        .arg(range)
        .arg(inside)
        .arg(inside == 1 ? QStringLiteral("address") : QStringLiteral("addresses"))
        .arg(others)
        .arg(others == 1 ? QStringLiteral("id") : QStringLiteral("ids"))
        .arg(outside.join(QStringLiteral(", ")));
}

// The ids outside the unit addresses that answered: an MBAP server answers 0 and 255 for itself,
// so they are no devices of their own.
QList<int> answeredOutside(const QList<UnitProbe> &probes)
{
    QList<int> ids;
    for (const UnitProbe &p : probes) {
        if (p.isPresent() && (p.unit < 1 || p.unit > 247))
            ids.append(p.unit);
    }
    return ids;
}

QString endText(JobEnd end)
{
    switch (end) {
    case JobEnd::Completed: return QStringLiteral("completed");
    case JobEnd::Stopped: return QStringLiteral("stopped (Ctrl-C): the rest was not asked");
    case JobEnd::TimeLimit: return QStringLiteral("time limit reached (--max-time): the rest was not asked");
    case JobEnd::LinkError: return QStringLiteral("ended by a link error: the rest was not asked");
    case JobEnd::RequestLimit: return QStringLiteral("request limit reached (--max-requests): the rest was not asked");
    }
    return {};
}

const char *tableName(quint8 function)
{
    switch (function) {
    case 1: return "coils (01)";
    case 2: return "discrete inputs (02)";
    case 3: return "holding registers (03)";
    default: return "input registers (04)";
    }
}

QString functionLabel(const FunctionSupport &s)
{
    QString label = hex2(s.function);
    if (s.subFunction >= 0)
        label += (s.function == 0x2B ? QStringLiteral("/") : QStringLiteral("/")) + QStringLiteral("%1").arg(s.subFunction, s.function == 0x08 ? 4 : 2, 16, QLatin1Char('0')).toUpper();
    return label;
}

QString answerText(const FunctionSupport &s)
{
    switch (s.answer) {
    case FunctionSupport::Answer::Answers: return QStringLiteral("answers");
    case FunctionSupport::Answer::Exception:
        return QStringLiteral("exception %1%2").arg(hex2(s.exceptionCode), s.exceptionCode == 0x01 ? QStringLiteral(" (not supported)")
                                                             : s.fromGateway()       ? QStringLiteral(" (gateway: no device)")
                                                                                     : QStringLiteral(" (supported)"));
    case FunctionSupport::Answer::Silent: return QStringLiteral("silent");
    case FunctionSupport::Answer::NotProbed: return QStringLiteral("not probed");
    }
    return {};
}

const char *answerName(FunctionSupport::Answer a)
{
    switch (a) {
    case FunctionSupport::Answer::Answers: return "answers";
    case FunctionSupport::Answer::Exception: return "exception";
    case FunctionSupport::Answer::Silent: return "silent";
    case FunctionSupport::Answer::NotProbed: return "not_probed";
    }
    return "silent";
}

} // namespace

int ScanReport::devicesFound(const QList<UnitProbe> &probes)
{
    int found = 0;
    for (const UnitProbe &p : probes)
        found += p.isPresent() && p.unit >= 1 && p.unit <= 247 ? 1 : 0;
    return found;
}

QString ScanReport::durationText(qint64 ms)
{
    if (ms < 1000)
        return QStringLiteral("%1 ms").arg(ms);
    if (ms < 60000)
        return QStringLiteral("%1 s").arg(QString::number(double(ms) / 1000.0, 'f', 1));
    return QStringLiteral("%1m %2s").arg(ms / 60000).arg((ms / 1000) % 60, 2, 10, QLatin1Char('0'));
}

QString ScanReport::progressText(const QString &what, const JobProgress &p, const QString &detail)
{
    QString text = QStringLiteral("%1 %2/%3").arg(what).arg(p.done).arg(p.total);
    if (what == QLatin1String("ids"))
        text += QStringLiteral("  found %1").arg(p.found);
    if (!detail.isEmpty())
        text += QStringLiteral("  ") + detail;
    text += QStringLiteral("  %1, about %2 left  (Ctrl-C stops)").arg(durationText(p.elapsedMs), durationText(p.remainingMs));
    return text;
}

QString ScanReport::unitsText(const UnitScanSettings &settings, const QList<UnitProbe> &probes,
                              const JobProgress &progress, JobEnd end, bool all)
{
    QString text;
    text += QStringLiteral("SCAN %1  units %2  function %3 address %4 quantity %5  timeout %6 ms  gap %7 ms\n")
                .arg(settings.url.toString(), unitRangeText(settings.firstUnit, settings.lastUnit))
                .arg(hex2(settings.function))
                .arg(settings.address)
                .arg(settings.quantity)
                .arg(settings.timeoutMs)
                .arg(settings.gapMs);
    text += QStringLiteral("%1  %2  %3  %4\n")
                .arg(QStringLiteral("UNIT"), -7)
                .arg(QStringLiteral("RESULT"), -26)
                .arg(QStringLiteral("LATENCY"), -10)
                .arg(QStringLiteral("DETAIL"));
    // Ids that found nothing are grouped in runs of the same result ("3-247  gateway_target_failed"),
    // unless --all asks for one line each; every id with a device gets a line of its own.
    for (qsizetype i = 0; i < probes.size();) {
        const UnitProbe &p = probes.at(i);
        qsizetype j = i + 1;
        if (!all && !p.isPresent()) {
            while (j < probes.size() && probes.at(j).kind == p.kind && probes.at(j).exceptionCode == p.exceptionCode
                   && !probes.at(j).isPresent() && p.kind != UnitProbeKind::WrongUnit && p.kind != UnitProbeKind::Garbage
                   && p.kind != UnitProbeKind::Echo)
                ++j;
        }
        QString detail;
        switch (p.kind) {
        case UnitProbeKind::Exception:
        case UnitProbeKind::GatewayPathUnavailable:
        case UnitProbeKind::GatewayTargetFailed:
        case UnitProbeKind::WrongUnit:
            detail = p.summary();
            break;
        case UnitProbeKind::Garbage:
        case UnitProbeKind::LinkError:
            detail = p.problem;
            break;
        case UnitProbeKind::Echo:
            detail = QStringLiteral("read back: ") + HexText::format(p.response);
            break;
        default:
            break;
        }
        const QString ids = j - i > 1 ? QStringLiteral("%1-%2").arg(p.unit).arg(probes.at(j - 1).unit) : QString::number(p.unit);
        if (j - i > 1)
            detail = QStringLiteral("(%1 ids) ").arg(j - i) + detail;
        text += QStringLiteral("%1  %2  %3  %4\n")
                    .arg(ids, -7)
                    .arg(QString::fromLatin1(unitProbeKindName(p.kind)), -26)
                    .arg(j - i == 1 && p.latencyNs >= 0 ? latencyText(p.latencyNs) : QStringLiteral("-"), -10)
                    .arg(detail)
                    .trimmed()
                + QLatin1Char('\n');
        i = j;
    }
    QMap<UnitProbeKind, int> counts;
    for (const UnitProbe &p : probes)
        counts[p.kind]++;
    QStringList parts;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        parts.append(QStringLiteral("%1 %2").arg(it.value()).arg(QString::fromLatin1(unitProbeKindName(it.key()))));
    const QList<int> outside = answeredOutside(probes);
    QString found = UnitProbe::oneDeviceIgnoringUnitId(probes)
        ? QStringLiteral("every one of the %1 unit addresses asked answered: likely one device that ignores the unit id, "
                         "not %1 devices").arg(devicesFound(probes))
        : QStringLiteral("found %1 device(s)").arg(devicesFound(probes));
    if (!outside.isEmpty()) {
        QStringList ids;
        for (int id : outside)
            ids.append(QString::number(id));
        found += QStringLiteral(" at unit addresses 1-247; %1 %2 answered too, outside them (an MBAP server or gateway answering "
                                "for itself, no device of its own)")
                     .arg(outside.size() == 1 ? QStringLiteral("id") : QStringLiteral("ids"), ids.join(QStringLiteral(", ")));
    }
    text += QStringLiteral("\n%1 of %2 ids asked in %3: %4\n%5; %6\n")
                .arg(progress.done)
                .arg(progress.total)
                .arg(durationText(progress.elapsedMs))
                .arg(parts.join(QStringLiteral(", ")), found, endText(end));
    return text;
}

QJsonObject ScanReport::unitsJson(const UnitScanSettings &settings, const QList<UnitProbe> &probes,
                                  const JobProgress &progress, JobEnd end)
{
    QJsonArray units;
    for (const UnitProbe &p : probes) {
        QJsonObject o{{QStringLiteral("unit"), int(p.unit)},
                      {QStringLiteral("result"), QString::fromLatin1(unitProbeKindName(p.kind))},
                      {QStringLiteral("present"), p.isPresent()},
                      {QStringLiteral("summary"), p.summary()}};
        if (p.exceptionCode != 0)
            o.insert(QStringLiteral("exception_code"), int(p.exceptionCode));
        if (p.kind == UnitProbeKind::WrongUnit)
            o.insert(QStringLiteral("answered_unit"), int(p.answeredUnit));
        o.insert(QStringLiteral("latency_ms"), p.latencyNs >= 0 ? QJsonValue(double(p.latencyNs) / 1e6) : QJsonValue());
        if (!p.problem.isEmpty())
            o.insert(QStringLiteral("problem"), p.problem);
        o.insert(QStringLiteral("request"), HexText::format(p.request));
        if (!p.response.isEmpty())
            o.insert(QStringLiteral("response"), HexText::format(p.response));
        units.append(o);
    }
    return QJsonObject{
        {QStringLiteral("target"), settings.url.toString()},
        {QStringLiteral("first_unit"), settings.firstUnit},
        {QStringLiteral("last_unit"), settings.lastUnit},
        {QStringLiteral("outside_unit_addresses"), QJsonArray::fromStringList(outsideUnitAddresses(settings.firstUnit, settings.lastUnit))},
        {QStringLiteral("function"), int(settings.function)},
        {QStringLiteral("address"), int(settings.address)},
        {QStringLiteral("quantity"), int(settings.quantity)},
        {QStringLiteral("timeout_ms"), settings.timeoutMs},
        {QStringLiteral("gap_ms"), settings.gapMs},
        {QStringLiteral("asked"), progress.done},
        {QStringLiteral("found"), devicesFound(probes)}, // at unit addresses 1-247
        {QStringLiteral("ignores_unit_id"), UnitProbe::oneDeviceIgnoringUnitId(probes)},
        {QStringLiteral("answered_outside_unit_addresses"), [&] {
             QJsonArray ids;
             for (int id : answeredOutside(probes))
                 ids.append(id);
             return ids;
         }()},
        {QStringLiteral("elapsed_ms"), double(progress.elapsedMs)},
        {QStringLiteral("end"), QString::fromLatin1(jobEndName(end))},
        {QStringLiteral("units"), units},
    };
}

QString ScanReport::mapText(const RegisterMap &map, JobEnd end, qint64 elapsedMs)
{
    QString text = QStringLiteral("MAP unit %1\n").arg(map.unit);
    for (const TableMap &t : map.tables) {
        text += QStringLiteral("\n%1, addresses %2-%3 searched: ")
                    .arg(QString::fromLatin1(tableName(t.function)))
                    .arg(t.searchedFirst)
                    .arg(t.searchedLast);
        if (t.gatewayException != 0) {
            text += QStringLiteral("no device: exception %1 from a gateway (%2)\n")
                        .arg(hex2(t.gatewayException),
                             t.gatewayException == 0x0A ? QStringLiteral("no path to the unit")
                                                        : QStringLiteral("nothing answered behind it"));
            continue;
        }
        if (!t.supported) {
            text += QStringLiteral("function not answered (exception 01 or silence)\n");
            continue;
        }
        text += QStringLiteral("largest quantity %1, %2 requests\n")
                    .arg(t.maxQuantity > 0 ? QString::number(t.maxQuantity) : QStringLiteral("unknown"))
                    .arg(t.requests);
        if (t.blocks.isEmpty())
            text += QStringLiteral("  no address answered\n");
        for (const MapBlock &b : t.blocks)
            text += QStringLiteral("  %1-%2  (%3 addresses)\n").arg(b.address).arg(b.last()).arg(b.count());
        if (t.refusesGapReads())
            text += QStringLiteral("  reads over a gap refused (exception 02 at %1): no read spans two blocks\n").arg(t.firstGapRefusal);
    }
    if (!map.functions.isEmpty()) {
        text += QStringLiteral("\nOptional functions:\n");
        for (const FunctionSupport &s : map.functions)
            text += QStringLiteral("  %1  %2  %3\n").arg(functionLabel(s), -7).arg(answerText(s), -28).arg(s.note);
    }
    if (map.exceptionStatus >= 0)
        text += QStringLiteral("exception status (07): 0x%1\n").arg(hex2(map.exceptionStatus));
    if (!map.serverIdData.isEmpty())
        text += QStringLiteral("server id (11): %1\n").arg(HexText::format(map.serverIdData));
    text += QStringLiteral("\n%1 requests in %2; %3\n").arg(map.requests).arg(durationText(elapsedMs)).arg(endText(end));
    return text;
}

QJsonObject ScanReport::mapJson(const RegisterMap &map, JobEnd end, qint64 elapsedMs)
{
    QJsonArray tables;
    for (const TableMap &t : map.tables) {
        QJsonArray blocks;
        for (const MapBlock &b : t.blocks) {
            QJsonArray values;
            for (const quint16 v : b.values)
                values.append(int(v));
            blocks.append(QJsonObject{{QStringLiteral("first"), int(b.address)},
                                      {QStringLiteral("last"), b.last()},
                                      {QStringLiteral("values"), values}});
        }
        tables.append(QJsonObject{{QStringLiteral("function"), int(t.function)},
                                  {QStringLiteral("supported"), t.supported},
                                  {QStringLiteral("max_quantity"), t.maxQuantity},
                                  {QStringLiteral("gateway_exception"), t.gatewayException != 0 ? QJsonValue(int(t.gatewayException))
                                                                                                : QJsonValue(QJsonValue::Null)},
                                  {QStringLiteral("gap_reads_refused"), t.refusesGapReads()},
                                  {QStringLiteral("searched_first"), t.searchedFirst},
                                  {QStringLiteral("searched_last"), t.searchedLast},
                                  {QStringLiteral("requests"), t.requests},
                                  {QStringLiteral("blocks"), blocks}});
    }
    QJsonArray functions;
    for (const FunctionSupport &s : map.functions) {
        QJsonObject o{{QStringLiteral("function"), int(s.function)},
                      {QStringLiteral("answer"), QString::fromLatin1(answerName(s.answer))},
                      {QStringLiteral("known"), s.known()},
                      {QStringLiteral("note"), s.note}};
        if (s.subFunction >= 0)
            o.insert(QStringLiteral("sub_function"), s.subFunction);
        if (s.answer == FunctionSupport::Answer::Exception)
            o.insert(QStringLiteral("exception_code"), int(s.exceptionCode));
        functions.append(o);
    }
    QJsonObject o{{QStringLiteral("unit"), int(map.unit)},
                  {QStringLiteral("tables"), tables},
                  {QStringLiteral("functions"), functions},
                  {QStringLiteral("requests"), map.requests},
                  {QStringLiteral("elapsed_ms"), double(elapsedMs)},
                  {QStringLiteral("end"), QString::fromLatin1(jobEndName(end))}};
    if (map.exceptionStatus >= 0)
        o.insert(QStringLiteral("exception_status"), map.exceptionStatus);
    return o;
}

} // namespace mbscope::app
