#include "metricsregistry.h"

#include "metricname.h"

namespace mbscope {

MetricFamily &MetricsRegistry::gauge(const QString &name, const QString &help, const QStringList &labelNames)
{
    return make(name, help, MetricType::Gauge, labelNames, {});
}

MetricFamily &MetricsRegistry::counter(const QString &name, const QString &help, const QStringList &labelNames)
{
    return make(name, help, MetricType::Counter, labelNames, {});
}

MetricFamily &MetricsRegistry::histogram(const QString &name, const QString &help, const QStringList &labelNames,
                                         const QList<double> &buckets)
{
    return make(name, help, MetricType::Histogram, labelNames, buckets);
}

MetricFamily &MetricsRegistry::make(const QString &name, const QString &help, MetricType type,
                                    const QStringList &labelNames, const QList<double> &buckets)
{
    for (const auto &family : m_families) {
        if (family->name() != name)
            continue;
        if (family->type() != type || family->labelNames() != labelNames)
            m_problems.append(QStringLiteral("metric '%1' asked for again with another type or labels").arg(name));
        return *family;
    }
    if (const QString p = MetricName::problem(name, type == MetricType::Counter); !p.isEmpty())
        m_problems.append(p);
    for (const QString &label : labelNames) {
        if (const QString p = MetricName::labelProblem(label); !p.isEmpty())
            m_problems.append(QStringLiteral("%1: %2").arg(name, p));
    }
    if (help.isEmpty())
        m_problems.append(QStringLiteral("metric '%1' has no help text").arg(name));
    for (qsizetype i = 1; i < buckets.size(); ++i) {
        if (!(buckets.at(i - 1) < buckets.at(i)))
            m_problems.append(QStringLiteral("histogram '%1': bucket bounds do not increase at %2").arg(name).arg(i));
    }
    m_families.push_back(std::make_unique<MetricFamily>(name, help, type, labelNames, buckets));
    return *m_families.back();
}

const MetricFamily *MetricsRegistry::find(const QString &name) const
{
    for (const auto &family : m_families) {
        if (family->name() == name)
            return family.get();
    }
    return nullptr;
}

QList<const MetricFamily *> MetricsRegistry::families() const
{
    QList<const MetricFamily *> out;
    out.reserve(qsizetype(m_families.size()));
    for (const auto &family : m_families)
        out.append(family.get());
    return out;
}

void MetricsRegistry::clearSeries()
{
    for (const auto &family : m_families)
        family->clear();
}

} // namespace mbscope
