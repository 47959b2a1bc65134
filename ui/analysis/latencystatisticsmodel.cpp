#include "latencystatisticsmodel.h"

#include "common/coretext.h"
#include "common/histogramchart.h"

#include "exchange/statistics.h"
#include "protocol/functioncode.h"

#include <QtCore/QLocale>

#include <algorithm>

namespace mbscope {

namespace {

QString hexCode(int code)
{
    return QStringLiteral("0x") + QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace

LatencyStatisticsModel::LatencyStatisticsModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

QList<LatencyStatisticsModel::Row> LatencyStatisticsModel::rowsFor(const QList<Column> &columns)
{
    QList<Row> rows;
    const auto counter = [&rows, &columns](const QString &key, const QString &name, auto figure) {
        Row row{key, name, false, {}};
        for (const Column &column : columns)
            row.values.append(QVariant::fromValue<quint64>(figure(*column.statistics)));
        rows.append(row);
    };
    counter(QStringLiteral("count"), tr("Transactions"), [](const Statistics &s) { return s.count(); });
    counter(QStringLiteral("ok"), tr("Ok"), [](const Statistics &s) { return s.ok(); });
    counter(QStringLiteral("exceptions"), tr("Exceptions"), [](const Statistics &s) { return s.exceptions(); });
    for (int code = 0; code < 256; ++code) {
        const bool seen = std::any_of(columns.begin(), columns.end(), [code](const Column &column) {
            return column.statistics->exceptions(quint8(code)) != 0;
        });
        if (seen)
            counter(QStringLiteral("exception %1").arg(hexCode(code)),
                    tr("Exception %1 %2").arg(hexCode(code), fieldText(exceptionName(quint8(code)))),
                    [code](const Statistics &s) { return s.exceptions(quint8(code)); });
    }
    counter(QStringLiteral("timeouts"), tr("Timeouts"), [](const Statistics &s) { return s.timeouts(); });
    counter(QStringLiteral("crc_errors"), tr("CRC errors"), [](const Statistics &s) { return s.crcErrors(); });
    counter(QStringLiteral("malformed"), tr("Malformed"), [](const Statistics &s) { return s.malformed(); });
    counter(QStringLiteral("unexpected"), tr("Unexpected"), [](const Statistics &s) { return s.unexpected(); });
    counter(QStringLiteral("late"), tr("Late"), [](const Statistics &s) { return s.late(); });
    counter(QStringLiteral("link_errors"), tr("Link errors"), [](const Statistics &s) { return s.linkErrors(); });
    // Serial answers that came before the line could have carried them (a pseudo terminal, a
    // USB adapter that buffers): shown only when there are some, with their latency from the write.
    const bool outran = std::any_of(columns.begin(), columns.end(), [](const Column &column) {
        return column.statistics->outranLine() != 0;
    });
    if (outran)
        counter(QStringLiteral("outran_line"), tr("Faster than the line (from the write)"),
                [](const Statistics &s) { return s.outranLine(); });

    // Past a store's exact limit its percentiles are bin middles: the rows say so (the figures are
    // within LatencySamples::kRelativeError, under 0.1 %, of the exact ones).
    const bool binned = std::any_of(columns.begin(), columns.end(), [](const Column &column) {
        return !column.statistics->latency().isExact();
    });
    const QString approximate = binned ? tr(" (within 0.1 %)") : QString();
    const auto latency = [&rows, &columns](const QString &key, const QString &name, auto figure) {
        Row row{key, name, true, {}};
        for (const Column &column : columns) {
            const LatencySamples &samples = column.statistics->latency();
            row.values.append(samples.isEmpty() ? QVariant() : QVariant(figure(samples)));
        }
        rows.append(row);
    };
    latency(QStringLiteral("latency_min"), tr("Latency min"), [](const LatencySamples &l) { return double(l.minNs()); });
    latency(QStringLiteral("latency_mean"), tr("Latency mean"), [](const LatencySamples &l) { return l.meanNs(); });
    latency(QStringLiteral("latency_median"), tr("Latency median") + approximate, [](const LatencySamples &l) { return double(l.medianNs()); });
    latency(QStringLiteral("latency_p90"), tr("Latency p90") + approximate, [](const LatencySamples &l) { return double(l.percentileNs(90)); });
    latency(QStringLiteral("latency_p95"), tr("Latency p95") + approximate, [](const LatencySamples &l) { return double(l.percentileNs(95)); });
    latency(QStringLiteral("latency_p99"), tr("Latency p99") + approximate, [](const LatencySamples &l) { return double(l.percentileNs(99)); });
    latency(QStringLiteral("latency_max"), tr("Latency max"), [](const LatencySamples &l) { return double(l.maxNs()); });
    latency(QStringLiteral("latency_stddev"), tr("Latency std. deviation"), [](const LatencySamples &l) { return l.stddevNs(); });
    return rows;
}

void LatencyStatisticsModel::setColumns(const QList<Column> &columns)
{
    QList<Row> rows = rowsFor(columns);
    QStringList titles;
    double largestNs = 0;
    for (const Column &column : columns) {
        titles.append(column.title);
        if (!column.statistics->latency().isEmpty())
            largestNs = std::max(largestNs, double(column.statistics->latency().maxNs()));
    }
    const HistogramChart::Unit unit = HistogramChart::unitFor(largestNs);

    bool sameShape = titles.size() == m_titles.size() && rows.size() == m_rows.size();
    for (qsizetype i = 0; sameShape && i < rows.size(); ++i)
        sameShape = rows.at(i).key == m_rows.at(i).key;
    if (!sameShape) {
        beginResetModel();
        m_titles = titles;
        m_rows = rows;
        m_unitNs = unit.ns;
        m_unitName = unit.name;
        endResetModel();
        return;
    }
    const bool titlesChanged = titles != m_titles;
    m_titles = titles;
    m_rows = rows;
    m_unitNs = unit.ns;
    m_unitName = unit.name;
    if (titlesChanged)
        Q_EMIT headerDataChanged(Qt::Horizontal, 1, int(m_titles.size()));
    if (!m_rows.isEmpty())
        Q_EMIT dataChanged(index(0, 1), index(rowCount() - 1, columnCount() - 1));
}

int LatencyStatisticsModel::rowOf(const QString &key) const
{
    for (qsizetype i = 0; i < m_rows.size(); ++i) {
        if (m_rows.at(i).key == key)
            return int(i);
    }
    return -1;
}

QVariant LatencyStatisticsModel::value(const QString &key, int run) const
{
    const int row = rowOf(key);
    if (row < 0 || run < 0 || run >= m_rows.at(row).values.size())
        return {};
    return m_rows.at(row).values.at(run);
}

int LatencyStatisticsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int LatencyStatisticsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_titles.size()) + 1;
}

QVariant LatencyStatisticsModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Row &row = m_rows.at(index.row());
    if (index.column() == 0)
        return role == Qt::DisplayRole ? QVariant(row.name) : QVariant();
    const QVariant &value = row.values.at(index.column() - 1);
    switch (role) {
    case Qt::DisplayRole:
        if (!value.isValid())
            return tr("–");
        if (row.latency)
            return tr("%1 %2").arg(QLocale().toString(value.toDouble() / m_unitNs, 'f', m_unitNs >= 1e6 ? 3 : 1), m_unitName);
        return QLocale().toString(value.toULongLong());
    case Qt::UserRole:
        return value;
    case Qt::TextAlignmentRole:
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    default:
        return {};
    }
}

QVariant LatencyStatisticsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section < 0 || section > m_titles.size())
        return {};
    return section == 0 ? tr("Figure") : m_titles.at(section - 1);
}

} // namespace mbscope
