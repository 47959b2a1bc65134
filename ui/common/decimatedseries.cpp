#include "decimatedseries.h"

#include <algorithm>
#include <cmath>

namespace mbscope {

DecimatedSeries::DecimatedSeries(int budget)
    : m_budget(std::max(8, budget))
{
}

qint64 DecimatedSeries::indexOf(double key) const
{
    return qint64(std::floor((key - m_origin) / m_width));
}

void DecimatedSeries::add(double key, double value)
{
    if (m_added == 0)
        m_origin = key;
    ++m_added;
    const bool merge = !m_buckets.empty() && (m_width == 0 ? false : indexOf(key) <= m_buckets.back().index);
    if (!merge) {
        m_buckets.push_back({m_width == 0 ? 0 : indexOf(key), key, value, key, value});
        ++m_size;
    } else {
        Bucket &last = m_buckets.back();
        m_size -= last.points();
        if (value < last.lowValue) {
            last.lowKey = key;
            last.lowValue = value;
        }
        if (value > last.highValue) {
            last.highKey = key;
            last.highValue = value;
        }
        m_size += last.points();
    }
    if (m_size > m_budget)
        compact();
}

void DecimatedSeries::compact()
{
    // The first time, a quarter of the budget in buckets over the keys seen (two points each:
    // half the budget); after that twice as wide.
    const double span = m_buckets.back().highKey - m_origin;
    m_width = m_width == 0 ? std::max(span / double(m_budget / 4), 1e-12) : m_width * 2;
    std::vector<Bucket> merged;
    merged.reserve(std::size_t(m_budget / 2));
    m_size = 0;
    for (const Bucket &b : m_buckets) {
        const qint64 index = indexOf(std::min(b.lowKey, b.highKey));
        if (!merged.empty() && index <= merged.back().index) {
            Bucket &last = merged.back();
            m_size -= last.points();
            if (b.lowValue < last.lowValue) {
                last.lowKey = b.lowKey;
                last.lowValue = b.lowValue;
            }
            if (b.highValue > last.highValue) {
                last.highKey = b.highKey;
                last.highValue = b.highValue;
            }
            m_size += last.points();
        } else {
            Bucket copy = b;
            copy.index = index;
            merged.push_back(copy);
            m_size += copy.points();
        }
    }
    m_buckets.swap(merged);
    if (m_size > m_budget) // keys bunched in few buckets: wider still
        compact();
}

void DecimatedSeries::clear()
{
    m_buckets.clear();
    m_buckets.shrink_to_fit();
    m_origin = m_width = 0;
    m_added = 0;
    m_size = 0;
}

QList<double> DecimatedSeries::keys() const
{
    QList<double> out;
    out.reserve(m_size);
    for (const Bucket &b : m_buckets) {
        if (b.points() == 1) {
            out.append(b.lowKey);
        } else {
            out.append(std::min(b.lowKey, b.highKey));
            out.append(std::max(b.lowKey, b.highKey));
        }
    }
    return out;
}

QList<double> DecimatedSeries::values() const
{
    QList<double> out;
    out.reserve(m_size);
    for (const Bucket &b : m_buckets) {
        if (b.points() == 1) {
            out.append(b.lowValue);
        } else if (b.lowKey <= b.highKey) {
            out.append(b.lowValue);
            out.append(b.highValue);
        } else {
            out.append(b.highValue);
            out.append(b.lowValue);
        }
    }
    return out;
}

} // namespace mbscope
