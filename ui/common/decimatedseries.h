#pragma once

#include <QtCore/QList>
#include <QtCore/QtGlobal>

#include <vector>

namespace mbscope {

// Points of a plot whose keys only grow (latency over time), held within a fixed budget however
// long the run: every point is kept until there are more than budget of them; then the key axis
// is cut into equal buckets and each bucket keeps its lowest and its highest point (in key order),
// so a spike stays visible where it happened. Each time the budget is reached again the buckets
// double in width. Points added out of key order go into the last bucket.
class DecimatedSeries
{
public:
    static constexpr int kDefaultBudget = 20000;

    explicit DecimatedSeries(int budget = kDefaultBudget);

    void add(double key, double value);
    void clear();

    [[nodiscard]] qint64 added() const { return m_added; } // every point given since clear()
    [[nodiscard]] int size() const { return m_size; }      // points kept, at most budget()
    [[nodiscard]] int budget() const { return m_budget; }
    // The width of a bucket in keys; 0 while every point is kept.
    [[nodiscard]] double bucketWidth() const { return m_width; }
    // The points kept, in key order.
    [[nodiscard]] QList<double> keys() const;
    [[nodiscard]] QList<double> values() const;

private:
    struct Bucket {
        qint64 index = 0;
        double lowKey = 0;
        double lowValue = 0;
        double highKey = 0;
        double highValue = 0;
        [[nodiscard]] int points() const { return lowKey == highKey && lowValue == highValue ? 1 : 2; }
    };

    void compact();
    [[nodiscard]] qint64 indexOf(double key) const;

    int m_budget;
    std::vector<Bucket> m_buckets;
    double m_origin = 0;
    double m_width = 0;
    qint64 m_added = 0;
    int m_size = 0;
};

} // namespace mbscope
