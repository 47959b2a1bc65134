#include "watchruletable.h"

#include "rulepalette.h"

#include <QtGui/QColor>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>

namespace mbscope {

namespace {

constexpr WatchRule::Condition kConditions[] = {
    WatchRule::Condition::Above, WatchRule::Condition::Below,    WatchRule::Condition::Outside, WatchRule::Condition::Inside,
    WatchRule::Condition::Equal, WatchRule::Condition::NotEqual, WatchRule::Condition::Bits,
};

} // namespace

WatchRuleTable::WatchRuleTable(QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setObjectName(QStringLiteral("watchRules"));
    setHorizontalHeaderLabels({tr("Point"), tr("Condition"), tr("Low"), tr("High"), tr("For polls"), tr("Severity"),
                               tr("Colour"), tr("Message")});
    horizontalHeader()->setSectionResizeMode(MessageColumn, QHeaderView::Stretch);
    verticalHeader()->hide();
    setToolTip(tr("above: value > high; below: value < low; outside/inside: the range low..high; equal/not equal: low; "
                  "bits: raw AND low (a mask) not 0. Colour: #RRGGBB, empty for the severity's."));
}

QString WatchRuleTable::conditionName(WatchRule::Condition condition)
{
    switch (condition) {
    case WatchRule::Condition::Above: return tr("above");
    case WatchRule::Condition::Below: return tr("below");
    case WatchRule::Condition::Outside: return tr("outside");
    case WatchRule::Condition::Inside: return tr("inside");
    case WatchRule::Condition::Equal: return tr("equal");
    case WatchRule::Condition::NotEqual: return tr("not equal");
    case WatchRule::Condition::Bits: return tr("bits set");
    }
    return {};
}

void WatchRuleTable::setRow(int row, const WatchRule &rule)
{
    setItem(row, PointColumn, new QTableWidgetItem(rule.point));
    auto *condition = new QComboBox(this);
    for (WatchRule::Condition c : kConditions)
        condition->addItem(conditionName(c), int(c));
    condition->setCurrentIndex(condition->findData(int(rule.condition)));
    setCellWidget(row, ConditionColumn, condition);
    setItem(row, LowColumn, new QTableWidgetItem(QString::number(rule.low)));
    setItem(row, HighColumn, new QTableWidgetItem(QString::number(rule.high)));
    setItem(row, ForColumn, new QTableWidgetItem(QString::number(rule.forPolls)));
    auto *severity = new QComboBox(this);
    for (WatchSeverity s : {WatchSeverity::Info, WatchSeverity::Warning, WatchSeverity::Alarm})
        severity->addItem(RulePalette::severityName(s), int(s));
    severity->setCurrentIndex(severity->findData(int(rule.severity)));
    setCellWidget(row, SeverityColumn, severity);
    setItem(row, ColourColumn, new QTableWidgetItem(rule.colour));
    setItem(row, MessageColumn, new QTableWidgetItem(rule.message));
}

void WatchRuleTable::setRules(const QList<WatchRule> &rules)
{
    setRowCount(0);
    setRowCount(int(rules.size()));
    for (int row = 0; row < rules.size(); ++row)
        setRow(row, rules.at(row));
}

void WatchRuleTable::addRule(const QString &point)
{
    WatchRule rule;
    rule.point = point;
    const int row = rowCount();
    insertRow(row);
    setRow(row, rule);
    setCurrentCell(row, PointColumn);
}

void WatchRuleTable::removeCurrent()
{
    if (currentRow() >= 0)
        removeRow(currentRow());
}

QList<WatchRule> WatchRuleTable::rules(QStringList *problems) const
{
    QList<WatchRule> rules;
    auto text = [this](int row, int column) { return item(row, column) ? item(row, column)->text().trimmed() : QString(); };
    for (int row = 0; row < rowCount(); ++row) {
        const QString where = tr("rule %1").arg(row + 1);
        WatchRule rule;
        rule.point = text(row, PointColumn);
        if (rule.point.isEmpty()) {
            problems->append(tr("%1: name the point (its name or address)").arg(where));
            continue;
        }
        rule.condition = WatchRule::Condition(qobject_cast<QComboBox *>(cellWidget(row, ConditionColumn))->currentData().toInt());
        rule.severity = WatchSeverity(qobject_cast<QComboBox *>(cellWidget(row, SeverityColumn))->currentData().toInt());
        bool lowOk = false;
        bool highOk = false;
        bool forOk = false;
        rule.low = text(row, LowColumn).toDouble(&lowOk);
        rule.high = text(row, HighColumn).toDouble(&highOk);
        rule.forPolls = text(row, ForColumn).toInt(&forOk);
        if (!lowOk || !highOk) {
            problems->append(tr("%1: low and high must be numbers").arg(where));
            continue;
        }
        if (!forOk || rule.forPolls < 1) {
            problems->append(tr("%1: 'for polls' must be 1 or more").arg(where));
            continue;
        }
        rule.colour = text(row, ColourColumn);
        if (!rule.colour.isEmpty() && !(rule.colour.startsWith(QLatin1Char('#')) && rule.colour.size() == 7 && QColor(rule.colour).isValid())) {
            problems->append(tr("%1: colour '%2' is not #RRGGBB").arg(where, rule.colour));
            continue;
        }
        rule.message = text(row, MessageColumn);
        rules.append(rule);
    }
    return rules;
}

} // namespace mbscope
