#pragma once

#include "statistics.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <vector>

namespace mbscope {

// Statistics overall and per request item of a poll (Transaction::item), fed in one call.
// Transactions with no item (-1, a single send) count overall only.
class StatisticsSet
{
public:
    explicit StatisticsSet(const HistogramSpec &histogram = HistogramSpec::automatic());

    void add(const Transaction &transaction);
    void clear(); // counts and latencies gone; item names kept

    // Each item's latencies and the overall ones past limit are binned (Statistics); 0: all kept.
    void setExactLatencyLimit(std::size_t limit);

    // Names shown beside each item in JSON and the summary ("write bits", "write words").
    void setItemNames(const QStringList &names) { m_names = names; }

    [[nodiscard]] const Statistics &overall() const { return m_overall; }
    // Items seen so far: one past the highest index added (or named).
    [[nodiscard]] int itemCount() const;
    // The statistics of one item; empty ones for an index never seen.
    [[nodiscard]] const Statistics &item(int index) const;

    // The overall object of Statistics::toJson(), plus "items": [{"item": 0, "name": "...",
    // ...the same keys...}, ...] when there are items.
    [[nodiscard]] QJsonObject toJson() const;
    // The overall summary, then each item's under a heading "item 0 (write bits)".
    [[nodiscard]] QString summary() const;

private:
    HistogramSpec m_spec;
    Statistics m_overall;
    Statistics m_empty;
    std::vector<Statistics> m_items;
    QStringList m_names;
};

} // namespace mbscope
