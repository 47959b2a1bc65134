#include "statistics.h"

#include "protocol/functioncode.h"

#include <QtCore/QJsonArray>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

QJsonValue microseconds(double ns)
{
    return ns / 1000.0;
}

QString hexCode(int code)
{
    return QLatin1String("0x") + QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

QString padded(const char *label)
{
    return QString::fromUtf8(label).leftJustified(14);
}

} // namespace

LatencyUnit LatencyUnit::forTypical(qint64 typicalNs)
{
    if (typicalNs < 1000000)
        return {"µs", 1e3, 1};
    if (typicalNs < 10000000000LL)
        return {"ms", 1e6, 3};
    return {"s", 1e9, 3};
}

QString LatencyUnit::format(double valueNs) const
{
    return QString::number(valueNs / ns, 'f', decimals);
}

Statistics::Statistics(const HistogramSpec &histogram)
    : m_spec(histogram), m_histogram(Histogram::fromSpec(histogram))
{
}

void Statistics::add(const Transaction &transaction)
{
    bool answered = false;
    switch (transaction.status) {
    case TransactionStatus::Ok:
        ++m_ok;
        answered = true;
        break;
    case TransactionStatus::Exception:
        ++m_exceptions;
        ++m_exceptionsByCode[transaction.exceptionCode];
        answered = true;
        break;
    case TransactionStatus::Timeout:
        ++m_timeouts;
        break;
    case TransactionStatus::CrcError:
        ++m_crcErrors;
        break;
    case TransactionStatus::Malformed:
        ++m_malformed;
        break;
    case TransactionStatus::Unexpected:
        ++m_unexpected;
        break;
    case TransactionStatus::LinkError:
        ++m_linkErrors;
        break;
    case TransactionStatus::Broadcast:
        ++m_broadcasts;
        break;
    case TransactionStatus::Late:
        ++m_late;
        return; // its request was already counted, as a timeout
    }
    ++m_count;
    if (answered && transaction.doneNs > 0) {
        const qint64 ns = transaction.latencyNs();
        m_latency.add(ns);
        if (transaction.measuredFromLineEnd())
            ++m_fromLineEnd;
        else
            ++m_fromWrite;
        if (transaction.outranLine)
            ++m_outranLine;
        if (m_spec.kind != HistogramSpec::Kind::Auto)
            m_histogram.add(ns);
    }
}

void Statistics::clear()
{
    const bool onTheLine = m_onTheLine;
    const std::size_t limit = m_latency.exactLimit();
    *this = Statistics(m_spec);
    m_onTheLine = onTheLine;
    m_latency.setExactLimit(limit);
}

quint64 Statistics::failed() const
{
    return m_exceptions + m_timeouts + m_crcErrors + m_malformed + m_unexpected + m_linkErrors;
}

double Statistics::errorRate() const
{
    const quint64 wanted = m_count - m_broadcasts;
    return wanted == 0 ? 0.0 : double(failed()) / double(wanted);
}

QString Statistics::latencyOrigin() const
{
    if (m_onTheLine)
        return m_fromLineEnd > 0 || m_fromWrite > 0 ? QStringLiteral("the request's last byte as read off the line") : QString();
    if (m_fromLineEnd > 0 && m_fromWrite > 0)
        return QStringLiteral("the computed end of the request's transmission (%1 answers), the write (%2)")
            .arg(m_fromLineEnd)
            .arg(m_fromWrite);
    if (m_fromLineEnd > 0)
        return QStringLiteral("the computed end of the request's transmission (the write + its characters at the baud rate)");
    if (m_fromWrite > 0)
        return QStringLiteral("the request's write to the link");
    return {};
}

QString Statistics::outranLineWarning() const
{
    if (m_outranLine == 0)
        return {};
    return QStringLiteral("%1 of %2 answers came before the serial line could have carried the request and the answer "
                          "at its baud rate: the link does not honour it (a pseudo terminal, or a USB adapter that buffers); "
                          "those latencies are measured from the write")
        .arg(m_outranLine)
        .arg(m_latency.count());
}

Histogram Statistics::histogram() const
{
    if (m_spec.kind == HistogramSpec::Kind::Auto)
        return Histogram::autoFixed(m_latency, m_spec.maxBins);
    return m_histogram;
}

QJsonObject Statistics::toJson() const
{
    QJsonObject byCode;
    for (int code = 0; code < 256; ++code) {
        if (m_exceptionsByCode[std::size_t(code)] != 0)
            byCode.insert(hexCode(code), double(m_exceptionsByCode[std::size_t(code)]));
    }

    QJsonObject latency;
    const bool any = !m_latency.isEmpty();
    const auto figure = [any](double ns) { return any ? microseconds(ns) : QJsonValue(); };
    latency.insert(QStringLiteral("count"), double(m_latency.count()));
    latency.insert(QStringLiteral("min"), figure(double(m_latency.minNs())));
    latency.insert(QStringLiteral("mean"), figure(m_latency.meanNs()));
    latency.insert(QStringLiteral("median"), figure(double(m_latency.medianNs())));
    latency.insert(QStringLiteral("p90"), figure(double(m_latency.percentileNs(90))));
    latency.insert(QStringLiteral("p95"), figure(double(m_latency.percentileNs(95))));
    latency.insert(QStringLiteral("p99"), figure(double(m_latency.percentileNs(99))));
    latency.insert(QStringLiteral("max"), figure(double(m_latency.maxNs())));
    latency.insert(QStringLiteral("stddev"), figure(m_latency.stddevNs()));

    QJsonObject out{
        {QStringLiteral("count"), double(m_count)},
        {QStringLiteral("ok"), double(m_ok)},
        {QStringLiteral("exceptions"), double(m_exceptions)},
        {QStringLiteral("exceptions_by_code"), byCode},
        {QStringLiteral("timeouts"), double(m_timeouts)},
        {QStringLiteral("crc_errors"), double(m_crcErrors)},
        {QStringLiteral("malformed"), double(m_malformed)},
        {QStringLiteral("unexpected"), double(m_unexpected)},
        {QStringLiteral("late"), double(m_late)},
        {QStringLiteral("link_errors"), double(m_linkErrors)},
        {QStringLiteral("broadcasts"), double(m_broadcasts)},
        {QStringLiteral("latency_us"), latency},
        {QStringLiteral("histogram"), histogram().toJson()},
        {QStringLiteral("outran_line"), double(m_outranLine)},
    };
    if (m_onTheLine && (m_fromLineEnd > 0 || m_fromWrite > 0))
        out.insert(QStringLiteral("latency_from"), QStringLiteral("request_last_byte"));
    else if (m_fromLineEnd > 0 || m_fromWrite > 0)
        out.insert(QStringLiteral("latency_from"), m_fromLineEnd == 0 ? QStringLiteral("write")
                                                   : m_fromWrite == 0 ? QStringLiteral("line_end")
                                                                      : QStringLiteral("mixed"));
    return out;
}

QString Statistics::summary() const
{
    return summary({}, {});
}

QString Statistics::summary(const QString &latencyFrom, const QString &latencyTo) const
{
    QStringList lines;
    const auto counter = [&lines](const char *label, quint64 value, const QString &detail = {}) {
        QString line = padded(label) + QString::number(value).rightJustified(8);
        if (!detail.isEmpty())
            line += QLatin1String("  ") + detail;
        lines.append(line);
    };

    const quint64 wanted = m_count - m_broadcasts;
    QString share;
    if (wanted > 0)
        share = QStringLiteral("ok %1 (%2 %)  failed %3")
                    .arg(m_ok)
                    .arg(100.0 * double(m_ok) / double(wanted), 0, 'f', 1)
                    .arg(failed());
    counter("transactions", m_count, share);

    QStringList codes;
    for (int code = 0; code < 256; ++code) {
        if (const quint64 n = m_exceptionsByCode[std::size_t(code)]; n != 0)
            codes.append(QStringLiteral("%1 %2: %3")
                             .arg(hexCode(code), QString::fromLatin1(exceptionName(quint8(code))))
                             .arg(n));
    }
    counter("exceptions", m_exceptions, codes.join(QLatin1String(", ")));
    counter("timeouts", m_timeouts);
    counter("crc errors", m_crcErrors);
    counter("malformed", m_malformed);
    counter("unexpected", m_unexpected);
    counter("late", m_late);
    counter("link errors", m_linkErrors);
    counter("broadcasts", m_broadcasts);

    if (m_latency.isEmpty()) {
        lines.append(padded("latency") + QStringLiteral("no answers"));
    } else {
        const LatencyUnit unit = LatencyUnit::forTypical(m_latency.medianNs());
        const auto value = [&unit](double ns) { return unit.format(ns); };
        lines.append(padded((QByteArray("latency ") + unit.name).constData())
                     + QStringLiteral("min %1  mean %2  median %3  p90 %4  p95 %5  p99 %6  max %7  stddev %8  (%9 answers)")
                           .arg(value(double(m_latency.minNs())), value(m_latency.meanNs()),
                                value(double(m_latency.medianNs())), value(double(m_latency.percentileNs(90))),
                                value(double(m_latency.percentileNs(95))), value(double(m_latency.percentileNs(99))),
                                value(double(m_latency.maxNs())), value(m_latency.stddevNs()))
                           .arg(m_latency.count()));
        if (!latencyFrom.isEmpty())
            lines.append(padded("latency from") + latencyFrom + QStringLiteral(" to ") + latencyTo);
        else
            lines.append(padded("latency from") + latencyOrigin() + QStringLiteral(" to the answer's last byte"));
        if (m_outranLine > 0)
            lines.append(padded("warning") + outranLineWarning());
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace mbscope
