#include "session/pollbound.h"

#include "time/duration.h"

#include "exchange/statistics.h"

#include <QtCore/QStringList>

#include <cmath>

namespace mbscope {

namespace {

const char *const kCounters[] = {"count", "ok", "failed", "exceptions", "timeouts", "crc_errors", "malformed",
                                 "unexpected", "late", "link_errors", "broadcasts"};
const char *const kLatencies[] = {"min", "max", "mean", "median", "stddev"};

QString figureList()
{
    QStringList names;
    for (const char *c : kCounters)
        names.append(QLatin1String(c));
    names.append(QStringLiteral("error_rate"));
    for (const char *l : kLatencies)
        names.append(QLatin1String(l));
    names.append(QStringLiteral("pNN (p50, p95, p99.9)"));
    return names.join(QStringLiteral(", "));
}

QString latencyText(double ns)
{
    if (std::fabs(ns) >= 1e9)
        return QString::number(ns / 1e9, 'f', 3) + QStringLiteral(" s");
    if (std::fabs(ns) >= 1e6)
        return QString::number(ns / 1e6, 'f', 3) + QStringLiteral(" ms");
    if (std::fabs(ns) >= 1e3)
        return QString::number(ns / 1e3, 'f', 3) + QStringLiteral(" us");
    return QString::number(qint64(ns)) + QStringLiteral(" ns");
}

} // namespace

PollBound::Parsed PollBound::parse(QStringView input)
{
    const QString text = input.trimmed().toString();
    auto fail = [&](const QString &why) { return Parsed{std::nullopt, QStringLiteral("'%1': %2").arg(text, why)}; };
    if (text.isEmpty())
        return {std::nullopt, QStringLiteral("an empty bound: expected FIGURE OP VALUE [UNIT], such as \"p95 < 20 ms\"")};

    qsizetype at = 0;
    auto skipSpace = [&] {
        while (at < text.size() && text.at(at).isSpace())
            ++at;
    };
    // The figure: letters, digits, '_' and '.' (p99.9).
    const qsizetype figureStart = at;
    while (at < text.size() && (text.at(at).isLetterOrNumber() || text.at(at) == QLatin1Char('_') || text.at(at) == QLatin1Char('.')))
        ++at;
    PollBound b;
    b.text = text;
    b.figure = text.mid(figureStart, at - figureStart).toLower();
    if (b.figure.isEmpty())
        return fail(QStringLiteral("expected a figure at column %1, such as p95 or timeouts; figures: %2").arg(at + 1).arg(figureList()));

    bool known = false;
    for (const char *c : kCounters)
        known = known || b.figure == QLatin1String(c);
    if (known) {
        b.kind = Kind::Counter;
    } else if (b.figure == QLatin1String("error_rate")) {
        b.kind = Kind::Rate;
        known = true;
    } else {
        for (const char *l : kLatencies)
            known = known || b.figure == QLatin1String(l);
        if (!known && b.figure.size() > 1 && b.figure.at(0) == QLatin1Char('p')) {
            bool ok = false;
            const double p = b.figure.mid(1).toDouble(&ok);
            if (!ok || p < 0 || p > 100)
                return fail(QStringLiteral("'%1' is not a percentile: expected p0 to p100, such as p95 or p99.9").arg(b.figure));
            b.percentile = p;
            known = true;
        }
        b.kind = Kind::Latency;
    }
    if (!known)
        return fail(QStringLiteral("unknown figure '%1': expected one of %2").arg(b.figure, figureList()));

    skipSpace();
    static const struct { const char *text; Op op; } kOps[] = {
        {"<=", Op::LessEqual}, {">=", Op::GreaterEqual}, {"==", Op::Equal}, {"!=", Op::NotEqual}, {"<", Op::Less}, {">", Op::Greater},
    };
    bool opFound = false;
    for (const auto &o : kOps) {
        const QLatin1String sign(o.text);
        if (text.mid(at).startsWith(sign)) {
            b.op = o.op;
            at += sign.size();
            opFound = true;
            break;
        }
    }
    if (!opFound || (at < text.size() && QStringLiteral("<>=!").contains(text.at(at))))
        return fail(QStringLiteral("expected a comparison (<, <=, >, >=, ==, !=) after '%1' at column %2").arg(b.figure).arg(at + 1));

    skipSpace();
    const qsizetype numberStart = at;
    while (at < text.size() && (text.at(at).isDigit() || text.at(at) == QLatin1Char('.')))
        ++at;
    bool ok = false;
    const QString numberText = text.mid(numberStart, at - numberStart);
    const double number = numberText.toDouble(&ok);
    if (!ok)
        return fail(QStringLiteral("expected a number at column %1").arg(numberStart + 1));
    skipSpace();
    const QString unit = text.mid(at).trimmed().toLower();

    switch (b.kind) {
    case Kind::Counter:
        if (!unit.isEmpty())
            return fail(QStringLiteral("%1 is a count: '%2' after %3 is not expected").arg(b.figure, unit, numberText));
        if (number != std::trunc(number))
            return fail(QStringLiteral("%1 is a count: %2 is not a whole number").arg(b.figure, numberText));
        b.value = number;
        break;
    case Kind::Rate:
        if (!unit.isEmpty() && unit != QLatin1String("%"))
            return fail(QStringLiteral("error_rate is a percentage: expected '%' or nothing after %1, found '%2'").arg(numberText, unit));
        if (number > 100)
            return fail(QStringLiteral("error_rate is a percentage: %1 is beyond 100").arg(numberText));
        b.value = number;
        break;
    case Kind::Latency: {
        // The one duration grammar (time/duration.h), with the unit required.
        const DurationResult d = parseDuration(QStringView(text).mid(numberStart), Duration::UnitRequired);
        if (d.problem == DurationResult::Problem::UnitMissing)
            return fail(QStringLiteral("%1 is a latency: give a unit after %2 (ns, us, ms, s, min or h)").arg(b.figure, numberText));
        if (d.problem == DurationResult::Problem::TooLong)
            return fail(QStringLiteral("%1 %2 is beyond a year").arg(numberText, unit));
        if (!d.ok())
            return fail(QStringLiteral("'%1' is not a unit of time: expected ns, us, ms, s, min or h").arg(unit));
        b.value = double(d.ns);
        break;
    }
    }
    return {b, {}};
}

std::optional<double> PollBound::measure(const Statistics &stats) const
{
    switch (kind) {
    case Kind::Counter: {
        if (figure == QLatin1String("count"))
            return double(stats.count());
        if (figure == QLatin1String("ok"))
            return double(stats.ok());
        if (figure == QLatin1String("failed"))
            return double(stats.failed());
        if (figure == QLatin1String("exceptions"))
            return double(stats.exceptions());
        if (figure == QLatin1String("timeouts"))
            return double(stats.timeouts());
        if (figure == QLatin1String("crc_errors"))
            return double(stats.crcErrors());
        if (figure == QLatin1String("malformed"))
            return double(stats.malformed());
        if (figure == QLatin1String("unexpected"))
            return double(stats.unexpected());
        if (figure == QLatin1String("late"))
            return double(stats.late());
        if (figure == QLatin1String("link_errors"))
            return double(stats.linkErrors());
        if (figure == QLatin1String("broadcasts"))
            return double(stats.broadcasts());
        return std::nullopt;
    }
    case Kind::Rate:
        return stats.errorRate() * 100.0;
    case Kind::Latency: {
        const LatencySamples &l = stats.latency();
        if (l.isEmpty())
            return std::nullopt;
        if (figure == QLatin1String("min"))
            return double(l.minNs());
        if (figure == QLatin1String("max"))
            return double(l.maxNs());
        if (figure == QLatin1String("mean"))
            return l.meanNs();
        if (figure == QLatin1String("median"))
            return double(l.medianNs());
        if (figure == QLatin1String("stddev"))
            return l.stddevNs();
        return double(l.percentileNs(percentile));
    }
    }
    return std::nullopt;
}

bool PollBound::holds(double measured) const
{
    switch (op) {
    case Op::Less:
        return measured < value;
    case Op::LessEqual:
        return measured <= value;
    case Op::Greater:
        return measured > value;
    case Op::GreaterEqual:
        return measured >= value;
    case Op::Equal:
        return measured == value;
    case Op::NotEqual:
        return measured != value;
    }
    return false;
}

QString PollBound::describe(const Statistics &stats) const
{
    const std::optional<double> m = measure(stats);
    if (!m)
        return QStringLiteral("%1: no request was answered, so there is no latency").arg(figure);
    switch (kind) {
    case Kind::Counter:
        return QStringLiteral("%1 is %2").arg(figure).arg(qint64(*m));
    case Kind::Rate:
        return QStringLiteral("error_rate is %1 %").arg(QString::number(*m, 'f', 2));
    case Kind::Latency:
        break;
    }
    return QStringLiteral("%1 is %2").arg(figure, latencyText(*m));
}

} // namespace mbscope
