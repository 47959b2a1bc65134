#pragma once

#include "metricfamily.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>
#include <vector>

namespace mbscope {

// The metric families one process exposes, in the order they were made (the order they are
// written in). Asking again for a family by name gives the one that exists. Families live as long
// as the registry, so references to them stay valid; clearSeries() empties them all (a reloaded
// session's watches and registers are not those of the old one).
//
// A name or label name that breaks the format's rules or Prometheus's conventions is a problem
// recorded here (problems()); the family is still made, so a mistake shows in tests, not as a
// crash in a service.
class MetricsRegistry
{
public:
    MetricFamily &gauge(const QString &name, const QString &help, const QStringList &labelNames = {});
    MetricFamily &counter(const QString &name, const QString &help, const QStringList &labelNames = {});
    MetricFamily &histogram(const QString &name, const QString &help, const QStringList &labelNames,
                            const QList<double> &buckets);

    [[nodiscard]] const MetricFamily *find(const QString &name) const;
    [[nodiscard]] QList<const MetricFamily *> families() const;
    [[nodiscard]] const QStringList &problems() const { return m_problems; }

    void clearSeries();

private:
    MetricFamily &make(const QString &name, const QString &help, MetricType type, const QStringList &labelNames,
                       const QList<double> &buckets);

    std::vector<std::unique_ptr<MetricFamily>> m_families;
    QStringList m_problems;
};

} // namespace mbscope
