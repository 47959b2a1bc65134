#pragma once

#include "watch/watchdefinition.h"

#include <QtWidgets/QTableWidget>

namespace mbscope {

// The rules of a watch as an editable table: the point (name or address), the condition and its
// bounds, how many polls it must hold, its severity, colour and message.
class WatchRuleTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column { PointColumn, ConditionColumn, LowColumn, HighColumn, ForColumn, SeverityColumn, ColourColumn, MessageColumn, ColumnCount };

    explicit WatchRuleTable(QWidget *parent = nullptr);

    void setRules(const QList<WatchRule> &rules);
    [[nodiscard]] QList<WatchRule> rules(QStringList *problems) const;
    void addRule(const QString &point);
    void removeCurrent();

    // "above", "below"... in the window's language.
    [[nodiscard]] static QString conditionName(WatchRule::Condition condition);

private:
    void setRow(int row, const WatchRule &rule);
};

} // namespace mbscope
