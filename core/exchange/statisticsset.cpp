#include "statisticsset.h"

#include <QtCore/QJsonArray>

#include <algorithm>

namespace mbscope {

StatisticsSet::StatisticsSet(const HistogramSpec &histogram)
    : m_spec(histogram), m_overall(histogram), m_empty(histogram)
{
}

void StatisticsSet::add(const Transaction &transaction)
{
    m_overall.add(transaction);
    if (transaction.item < 0)
        return;
    const auto index = std::size_t(transaction.item);
    if (index >= m_items.size())
        m_items.resize(index + 1, m_empty);
    m_items[index].add(transaction);
}

void StatisticsSet::setExactLatencyLimit(std::size_t limit)
{
    m_overall.setExactLatencyLimit(limit);
    m_empty.setExactLatencyLimit(limit);
    for (Statistics &one : m_items)
        one.setExactLatencyLimit(limit);
}

void StatisticsSet::clear()
{
    m_overall.clear();
    m_items.clear();
}

int StatisticsSet::itemCount() const
{
    return std::max(int(m_items.size()), int(m_names.size()));
}

const Statistics &StatisticsSet::item(int index) const
{
    if (index < 0 || std::size_t(index) >= m_items.size())
        return m_empty;
    return m_items[std::size_t(index)];
}

QJsonObject StatisticsSet::toJson() const
{
    QJsonObject json = m_overall.toJson();
    const int n = itemCount();
    if (n == 0)
        return json;
    QJsonArray items;
    for (int i = 0; i < n; ++i) {
        QJsonObject one = item(i).toJson();
        one.insert(QStringLiteral("item"), i);
        if (i < m_names.size())
            one.insert(QStringLiteral("name"), m_names.at(i));
        items.append(one);
    }
    json.insert(QStringLiteral("items"), items);
    return json;
}

QString StatisticsSet::summary() const
{
    QString text = m_overall.summary();
    const int n = itemCount();
    for (int i = 0; i < n; ++i) {
        text += QStringLiteral("\nitem %1").arg(i);
        if (i < m_names.size() && !m_names.at(i).isEmpty())
            text += QStringLiteral(" (%1)").arg(m_names.at(i));
        text += QLatin1Char('\n') + item(i).summary();
    }
    return text;
}

} // namespace mbscope
