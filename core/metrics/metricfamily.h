#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <map>

namespace mbscope {

enum class MetricType : quint8 { Gauge, Counter, Histogram };

// One labelled series of a family: a gauge's or counter's value, or a histogram's buckets.
struct MetricSeries {
    double value = 0;             // gauge, counter
    QList<quint64> bucketCounts;  // histogram: observations per bucket (not cumulative), the last one +Inf
    double sum = 0;               // histogram
    quint64 count = 0;            // histogram
};

// A metric family as Prometheus sees it: one name, help text, type and label names, and a series
// per set of label values. Names follow the exposition format's rules and Prometheus's conventions
// (base units, counters ending in _total); the registry checks them when a family is made
// (MetricName). The label values are data (a watch's or register's name) and are escaped when
// written, never checked.
//
// A series exists from its first set/add/observe (or touch) until removed, so a counter that has
// not counted yet can still be shown as 0: rate() needs the zero to see the first increase.
class MetricFamily
{
public:
    MetricFamily(QString name, QString help, MetricType type, QStringList labelNames, QList<double> buckets = {});

    [[nodiscard]] const QString &name() const { return m_name; }
    [[nodiscard]] const QString &help() const { return m_help; }
    [[nodiscard]] MetricType type() const { return m_type; }
    [[nodiscard]] const QStringList &labelNames() const { return m_labelNames; }
    // Histogram upper bounds, increasing, without +Inf.
    [[nodiscard]] const QList<double> &buckets() const { return m_buckets; }

    // Label values in the order of labelNames() (missing ones are empty, extra ones ignored).
    void set(const QStringList &labelValues, double value);
    void add(const QStringList &labelValues, double amount = 1);
    void observe(const QStringList &labelValues, double value);
    // The same on a series of this family (at()).
    void observe(MetricSeries &series, double value) const;
    // The series exists (0, or an empty histogram) without changing it when it already did.
    void touch(const QStringList &labelValues);
    void remove(const QStringList &labelValues);
    // Every series whose label at labelIndex has this value ("all values of watch w").
    void removeWhere(int labelIndex, const QString &value);
    void clear()
    {
        m_series.clear();
        ++m_removals;
    }

    [[nodiscard]] const std::map<QStringList, MetricSeries> &series() const { return m_series; }
    // The series, or nullptr when it does not exist.
    [[nodiscard]] const MetricSeries *find(const QStringList &labelValues) const;

    // The series of these labels, made when it did not exist. The reference stays valid while
    // removals() stays the same (a series is only ever lost by remove, removeWhere or clear), so
    // a writer that updates the same series many times a second looks its labels up once
    // (MetricSeriesSlot).
    [[nodiscard]] MetricSeries &at(const QStringList &labelValues);
    [[nodiscard]] quint64 removals() const { return m_removals; }

private:
    [[nodiscard]] QStringList normalised(const QStringList &labelValues) const;

    QString m_name;
    QString m_help;
    MetricType m_type;
    QStringList m_labelNames;
    QList<double> m_buckets;
    std::map<QStringList, MetricSeries> m_series;
    quint64 m_removals = 0;
};

// A series found once and kept while its family has lost none (MetricFamily::removals).
class MetricSeriesSlot
{
public:
    // labels() is called only when the series must be looked up again.
    template<typename Labels>
    MetricSeries &get(MetricFamily &family, Labels labels)
    {
        if (!m_series || m_removals != family.removals()) {
            m_series = &family.at(labels());
            m_removals = family.removals();
        }
        return *m_series;
    }
    void forget() { m_series = nullptr; }

private:
    MetricSeries *m_series = nullptr;
    quint64 m_removals = 0;
};

} // namespace mbscope
