#include "metricfamily.h"

#include <algorithm>

namespace mbscope {

MetricFamily::MetricFamily(QString name, QString help, MetricType type, QStringList labelNames, QList<double> buckets)
    : m_name(std::move(name))
    , m_help(std::move(help))
    , m_type(type)
    , m_labelNames(std::move(labelNames))
    , m_buckets(std::move(buckets))
{
}

QStringList MetricFamily::normalised(const QStringList &labelValues) const
{
    if (labelValues.size() == m_labelNames.size())
        return labelValues;
    QStringList values = labelValues.mid(0, m_labelNames.size());
    while (values.size() < m_labelNames.size())
        values.append(QString());
    return values;
}

MetricSeries &MetricFamily::at(const QStringList &labelValues)
{
    const QStringList key = normalised(labelValues);
    auto it = m_series.find(key);
    if (it == m_series.end()) {
        it = m_series.emplace(key, MetricSeries{}).first;
        if (m_type == MetricType::Histogram)
            it->second.bucketCounts.resize(m_buckets.size() + 1);
    }
    return it->second;
}

void MetricFamily::set(const QStringList &labelValues, double value)
{
    at(labelValues).value = value;
}

void MetricFamily::add(const QStringList &labelValues, double amount)
{
    at(labelValues).value += amount;
}

void MetricFamily::observe(const QStringList &labelValues, double value)
{
    observe(at(labelValues), value);
}

void MetricFamily::observe(MetricSeries &s, double value) const
{
    // The first bound the value does not exceed (le: less than or equal); past the last, +Inf.
    const auto bound = std::lower_bound(m_buckets.cbegin(), m_buckets.cend(), value);
    ++s.bucketCounts[bound - m_buckets.cbegin()];
    s.sum += value;
    ++s.count;
}

void MetricFamily::touch(const QStringList &labelValues)
{
    (void)at(labelValues);
}

void MetricFamily::remove(const QStringList &labelValues)
{
    if (m_series.erase(normalised(labelValues)) > 0)
        ++m_removals;
}

void MetricFamily::removeWhere(int labelIndex, const QString &value)
{
    for (auto it = m_series.begin(); it != m_series.end();) {
        if (it->first.value(labelIndex) == value) {
            it = m_series.erase(it);
            ++m_removals;
        } else
            ++it;
    }
}

const MetricSeries *MetricFamily::find(const QStringList &labelValues) const
{
    const auto it = m_series.find(normalised(labelValues));
    return it == m_series.end() ? nullptr : &it->second;
}

} // namespace mbscope
