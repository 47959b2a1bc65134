#include "watchruletable.h"

#include "rulepalette.h"

#include "watch/watchruleevaluator.h"
#include "watch/watchrulethresholds.h"

#include <QtGui/QColor>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>

#include <tuple>

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
    setToolTip(tr("above: value > High; below: value < Low; outside/inside: the range Low..High; equal/not equal: Low; "
                  "bits: raw AND Low (a mask) not 0. A threshold the condition does not use is greyed out and empty. "
                  "Colour: #RRGGBB, empty for the severity's."));
}

QString WatchRuleTable::thresholdName(WatchRuleThresholds::Field field)
{
    return field == WatchRuleThresholds::Field::Low ? tr("Low") : tr("High");
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
    using Field = WatchRuleThresholds::Field;
    const auto threshold = [&rule](Field field, double value) {
        return WatchRuleThresholds::uses(rule.condition, field) ? QString::number(value, 'g', 15) : QString();
    };
    setItem(row, LowColumn, new QTableWidgetItem(threshold(Field::Low, rule.low)));
    setItem(row, HighColumn, new QTableWidgetItem(threshold(Field::High, rule.high)));
    showThresholds(row);
    connect(condition, &QComboBox::currentIndexChanged, this, [this, condition] {
        for (int r = 0; r < rowCount(); ++r) {
            if (cellWidget(r, ConditionColumn) == condition)
                showThresholds(r);
        }
    });
    setItem(row, ForColumn, new QTableWidgetItem(QString::number(rule.forPolls)));
    auto *severity = new QComboBox(this);
    for (WatchSeverity s : {WatchSeverity::Info, WatchSeverity::Warning, WatchSeverity::Alarm})
        severity->addItem(RulePalette::severityName(s), int(s));
    severity->setCurrentIndex(severity->findData(int(rule.severity)));
    setCellWidget(row, SeverityColumn, severity);
    setItem(row, ColourColumn, new QTableWidgetItem(rule.colour));
    setItem(row, MessageColumn, new QTableWidgetItem(rule.message));
}

WatchRule::Condition WatchRuleTable::condition(int row) const
{
    return WatchRule::Condition(qobject_cast<QComboBox *>(cellWidget(row, ConditionColumn))->currentData().toInt());
}

void WatchRuleTable::showThresholds(int row)
{
    using Field = WatchRuleThresholds::Field;
    const WatchRule::Condition c = condition(row);
    QTableWidgetItem *low = item(row, LowColumn);
    QTableWidgetItem *high = item(row, HighColumn);
    if (!low || !high)
        return;
    // A condition of one threshold takes over the number of the one it no longer uses ("below 10"
    // made "above" is "above 10"), so that switching never hides a number the rule still holds.
    const bool usesLow = WatchRuleThresholds::uses(c, Field::Low);
    const bool usesHigh = WatchRuleThresholds::uses(c, Field::High);
    if (usesLow && !usesHigh && low->text().trimmed().isEmpty())
        low->setText(high->text());
    if (usesHigh && !usesLow && high->text().trimmed().isEmpty())
        high->setText(low->text());
    const QString name = conditionName(c);
    for (auto [cell, used, field] : {std::tuple{low, usesLow, Field::Low}, std::tuple{high, usesHigh, Field::High}}) {
        if (used) {
            cell->setFlags(cell->flags() | Qt::ItemIsEditable | Qt::ItemIsEnabled);
            cell->setToolTip(QString());
        } else {
            cell->setText(QString());
            cell->setFlags(cell->flags() & ~(Qt::ItemIsEditable | Qt::ItemIsEnabled));
            cell->setToolTip(tr("'%1' does not use %2").arg(name, thresholdName(field)));
        }
    }
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

QList<WatchRule> WatchRuleTable::rules(const WatchDefinition &watch, QStringList *problems) const
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
        rule.condition = condition(row);
        rule.severity = WatchSeverity(qobject_cast<QComboBox *>(cellWidget(row, SeverityColumn))->currentData().toInt());
        // Each condition reads exactly the thresholds it shows: a number in a threshold it does
        // not use is refused, never silently ignored.
        bool thresholdsOk = true;
        using Field = WatchRuleThresholds::Field;
        for (auto [column, field, value] : {std::tuple{int(LowColumn), Field::Low, &rule.low},
                                            std::tuple{int(HighColumn), Field::High, &rule.high}}) {
            const QString name = thresholdName(field);
            const QString given = text(row, column);
            if (!WatchRuleThresholds::uses(rule.condition, field)) {
                if (!given.isEmpty()) {
                    problems->append(tr("%1: %2: '%3' does not use %2; clear it (it holds %4)")
                                         .arg(where, name, conditionName(rule.condition), given));
                    thresholdsOk = false;
                }
                continue;
            }
            bool ok = false;
            *value = given.toDouble(&ok);
            if (!ok) {
                problems->append(given.isEmpty() ? tr("%1: %2: '%3' needs a number here").arg(where, name, conditionName(rule.condition))
                                                 : tr("%1: %2: '%3' is not a number").arg(where, name, given));
                thresholdsOk = false;
            }
        }
        if (!thresholdsOk)
            continue;
        bool forOk = false;
        rule.forPolls = text(row, ForColumn).toInt(&forOk);
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
        // What the session reader refuses in a file, refused here with the column to correct.
        if (WatchRuleEvaluator::ruleAddress(watch, rule.point) < 0) {
            problems->append(tr("%1: Point: '%2' is neither a point's name nor an address of the watch").arg(where, rule.point));
            continue;
        }
        if (const auto problem = WatchRuleThresholds::problem(watch, rule)) {
            problems->append(tr("%1: %2: %3").arg(where, thresholdName(problem->field), problem->message));
            continue;
        }
        rules.append(rule);
    }
    return rules;
}

} // namespace mbscope
