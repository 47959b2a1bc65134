#include "replay/replayresult.h"

#include "protocol/functioncode.h"
#include "protocol/hextext.h"
#include "replay/replayscript.h"

#include <QtCore/QJsonArray>

namespace mbscope {

namespace {

QString ms(qint64 ns)
{
    return QString::number(double(ns) / 1e6, 'f', 3);
}

QJsonValue latencyJson(const Statistics &s)
{
    const LatencySamples &l = s.latency();
    if (l.isEmpty())
        return QJsonValue::Null;
    return QJsonObject{{QStringLiteral("count"), double(l.count())},
                       {QStringLiteral("min"), double(l.minNs()) / 1000.0},
                       {QStringLiteral("median"), double(l.medianNs()) / 1000.0},
                       {QStringLiteral("p95"), double(l.percentileNs(95.0)) / 1000.0},
                       {QStringLiteral("max"), double(l.maxNs()) / 1000.0}};
}

QString requestText(const ReplayExchange &e)
{
    const quint8 function = e.requestPdu.isEmpty() ? 0 : quint8(e.requestPdu.at(0));
    return QStringLiteral("unit %1 %2 %3").arg(e.unitId).arg(QLatin1String(functionName(function)), HexText::format(e.requestPdu));
}

QJsonArray ignoredJson(const AnswerComparison::Result &comparison)
{
    QJsonArray out;
    for (const AnswerComparison::Result::Ignored &i : comparison.ignored)
        out.append(QJsonObject{{QStringLiteral("field"), i.selector}, {QStringLiteral("difference"), i.difference}});
    return out;
}

} // namespace

qsizetype ReplayResult::count(AnswerComparison::Verdict verdict) const
{
    qsizetype n = 0;
    for (const ReplayOutcome &o : outcomes)
        n += o.comparison.verdict == verdict ? 1 : 0;
    return n;
}

QList<ReplayResult::IgnoredCount> ReplayResult::ignoredCounts() const
{
    QList<IgnoredCount> counts;
    for (const QString &selector : ignoredSelectors)
        counts.append({selector, 0, {}});
    for (const ReplayOutcome &o : outcomes) {
        for (IgnoredCount &c : counts) {
            for (const AnswerComparison::Result::Ignored &i : o.comparison.ignored) {
                if (i.selector != c.selector)
                    continue;
                if (c.answers++ == 0)
                    c.first = QStringLiteral("%1 (request #%2)").arg(i.difference).arg(o.index + 1);
                break;
            }
        }
    }
    return counts;
}

QString ReplayResult::latencyLine() const
{
    const LatencySamples &before = recorded.latency();
    const LatencySamples &after = replayed.latency();
    QString line = QStringLiteral("latency ms    recorded ");
    line += before.isEmpty() ? QStringLiteral("(no answers)")
                             : QStringLiteral("median %1  p95 %2").arg(ms(before.medianNs()), ms(before.percentileNs(95.0)));
    line += QStringLiteral("   now ");
    line += after.isEmpty() ? QStringLiteral("(no answers)")
                            : QStringLiteral("median %1  p95 %2").arg(ms(after.medianNs()), ms(after.percentileNs(95.0)));
    if (!before.isEmpty() && !after.isEmpty() && before.medianNs() > 0 && before.percentileNs(95.0) > 0) {
        const auto change = [](qint64 was, qint64 is) {
            const double percent = 100.0 * double(is - was) / double(was);
            return QStringLiteral("%1%2 %").arg(percent >= 0 ? QStringLiteral("+") : QString()).arg(percent, 0, 'f', 1);
        };
        line += QStringLiteral("   (median %1, p95 %2)")
                    .arg(change(before.medianNs(), after.medianNs()), change(before.percentileNs(95.0), after.percentileNs(95.0)));
    }
    return line;
}

QString ReplayResult::summary(const ReplayScript &script, int maxListed) const
{
    QString text;
    int listed = 0;
    for (const ReplayOutcome &o : outcomes) {
        if (o.comparison.matched())
            continue;
        if (listed++ == maxListed) {
            text += QStringLiteral("... (%1 more differing answers not listed; --json lists them all)\n").arg(differed() - maxListed);
            break;
        }
        const ReplayExchange &e = script.exchanges().at(size_t(o.index));
        text += QStringLiteral("#%1 %2: %3\n").arg(o.index + 1).arg(requestText(e), AnswerComparison::verdictName(o.comparison.verdict));
        for (const QString &d : o.comparison.differences)
            text += QStringLiteral("    %1\n").arg(d);
        for (const AnswerComparison::Result::Ignored &i : o.comparison.ignored)
            text += QStringLiteral("    %1 (ignored: --ignore %2)\n").arg(i.difference, i.selector);
    }
    if (listed > 0)
        text += QLatin1Char('\n');
    if (!skippedWrites.isEmpty()) {
        text += QStringLiteral("not sent: the recording's writes (--send-writes sends them)\n");
        for (qsizetype i = 0; i < skippedWrites.size(); ++i) {
            if (i == maxListed) {
                text += QStringLiteral("... (%1 more writes not listed; --json lists them all)\n").arg(skippedWrites.size() - maxListed);
                break;
            }
            text += QStringLiteral("%1: not sent\n").arg(skippedWrites.at(i).text());
        }
        text += QLatin1Char('\n');
    }
    text += QStringLiteral("replayed      %1 of %2 requests%3\n")
                .arg(outcomes.size())
                .arg(script.size())
                .arg(interrupted ? QStringLiteral(" (interrupted)") : QString());
    if (!skippedWrites.isEmpty())
        text += QStringLiteral("skipped       %1 %2, not sent (--send-writes sends them)\n")
                    .arg(skippedWrites.size())
                    .arg(skippedWrites.size() == 1 ? QStringLiteral("write") : QStringLiteral("writes"));
    text += QStringLiteral("matched       %1\n").arg(count(AnswerComparison::Verdict::Match));
    text += QStringLiteral("differed      %1  (values %2, outcome %3, missing answers %4)\n")
                .arg(differed())
                .arg(count(AnswerComparison::Verdict::ValuesDiffer))
                .arg(count(AnswerComparison::Verdict::OutcomeDiffers))
                .arg(count(AnswerComparison::Verdict::MissingAnswer));
    for (const IgnoredCount &c : ignoredCounts()) {
        text += QStringLiteral("ignored       %1: ").arg(c.selector);
        text += c.answers == 0 ? QStringLiteral("no answer differed there\n")
                               : QStringLiteral("differed in %1 answer(s), not counted; first %2\n").arg(c.answers).arg(c.first);
    }
    text += latencyLine() + QLatin1Char('\n');
    return text;
}

QJsonObject ReplayResult::toJson(const ReplayScript &script) const
{
    QJsonArray differences;
    for (const ReplayOutcome &o : outcomes) {
        if (o.comparison.matched())
            continue;
        const ReplayExchange &e = script.exchanges().at(size_t(o.index));
        differences.append(QJsonObject{{QStringLiteral("request"), double(o.index + 1)},
                                       {QStringLiteral("unit"), e.unitId},
                                       {QStringLiteral("pdu"), HexText::format(e.requestPdu)},
                                       {QStringLiteral("verdict"), AnswerComparison::verdictName(o.comparison.verdict)},
                                       {QStringLiteral("recorded"), HexText::format(e.recorded.response)},
                                       {QStringLiteral("now"), HexText::format(o.replayed.response)},
                                       {QStringLiteral("differences"), QJsonArray::fromStringList(o.comparison.differences)},
                                       {QStringLiteral("ignored"), ignoredJson(o.comparison)}});
    }
    QJsonArray skipped;
    for (const RecordedWrite &w : skippedWrites)
        skipped.append(w.toJson());
    QJsonArray ignored;
    for (const IgnoredCount &c : ignoredCounts()) {
        ignored.append(QJsonObject{{QStringLiteral("field"), c.selector},
                                   {QStringLiteral("answers"), double(c.answers)},
                                   {QStringLiteral("first"), c.first.isEmpty() ? QJsonValue() : QJsonValue(c.first)}});
    }
    return QJsonObject{{QStringLiteral("target"), target},
                       {QStringLiteral("requests"), double(script.size())},
                       {QStringLiteral("replayed"), double(outcomes.size())},
                       {QStringLiteral("matched"), double(count(AnswerComparison::Verdict::Match))},
                       {QStringLiteral("values_differ"), double(count(AnswerComparison::Verdict::ValuesDiffer))},
                       {QStringLiteral("outcome_differs"), double(count(AnswerComparison::Verdict::OutcomeDiffers))},
                       {QStringLiteral("missing_answers"), double(count(AnswerComparison::Verdict::MissingAnswer))},
                       {QStringLiteral("skipped_writes"), double(skippedWrites.size())},
                       {QStringLiteral("interrupted"), interrupted},
                       {QStringLiteral("elapsed_ms"), double(elapsedNs) / 1e6},
                       {QStringLiteral("differences"), differences},
                       {QStringLiteral("skipped"), skipped},
                       {QStringLiteral("ignored"), ignored},
                       {QStringLiteral("latency_us"),
                        QJsonObject{{QStringLiteral("recorded"), latencyJson(recorded)}, {QStringLiteral("replayed"), latencyJson(replayed)}}}};
}

} // namespace mbscope
