#pragma once

#include "watch/watchdefinition.h"
#include "watch/watchrulethresholds.h"

#include <QtWidgets/QTableWidget>

namespace mbscope {

// The rules of a watch as an editable table: the point (name or address), the condition and the
// bounds it uses (the others greyed out and empty), how many polls it must hold, its severity, colour and message.
class WatchRuleTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column { PointColumn, ConditionColumn, LowColumn, HighColumn, ForColumn, SeverityColumn, ColourColumn, MessageColumn, ColumnCount };

    explicit WatchRuleTable(QWidget *parent = nullptr);

    void setRules(const QList<WatchRule> &rules);
    // The rules of watch (its function and points: a rule names one of its addresses, and a
    // threshold its point can reach); a row with a problem is left out and said in problems
    // ("rule 2: Low: ...", by row and column).
    [[nodiscard]] QList<WatchRule> rules(const WatchDefinition &watch, QStringList *problems) const;
    void addRule(const QString &point);
    void removeCurrent();

    // "above", "below"... in the window's language.
    [[nodiscard]] static QString conditionName(WatchRule::Condition condition);
    // "Low" or "High", as the columns are headed.
    [[nodiscard]] static QString thresholdName(WatchRuleThresholds::Field field);

private:
    void setRow(int row, const WatchRule &rule);
    [[nodiscard]] WatchRule::Condition condition(int row) const;
    // Greys out and empties the thresholds the row's condition does not use.
    void showThresholds(int row);
};

} // namespace mbscope
