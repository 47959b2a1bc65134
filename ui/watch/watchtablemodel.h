#pragma once

#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>

namespace mbscope {

// One watch's values as a table: a row per value the decoder reads (a point, or an address no
// point names), columns address, Modicon reference, name, value, unit, rule and the time of the
// last change. Thin: the rows are the runner's WatchPointValues as they come; a sample only
// touches the rows whose text changed (one dataChanged over their span), so 20 watches of 125
// registers at 10 polls a second cost the GUI thread little.
class WatchTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { AddressColumn, ReferenceColumn, NameColumn, ValueColumn, UnitColumn, RuleColumn, ChangedColumn, ColumnCount };
    // The row's point index in the definition (-1: an unnamed address), and whether it is writable.
    static constexpr int PointRole = Qt::UserRole + 1;
    static constexpr int WritableRole = Qt::UserRole + 2;

    explicit WatchTableModel(QObject *parent = nullptr);

    // Rows laid out as the decoder reads the definition, values not known yet.
    void setDefinition(const WatchDefinition &watch);
    [[nodiscard]] const WatchDefinition &definition() const { return m_watch; }

    void applySample(const WatchSample &sample);
    void applyRule(const WatchRuleEvent &event);
    // Rules that hold now.
    [[nodiscard]] int activeRules() const;
    [[nodiscard]] qint64 lastSampleMs() const { return m_lastSampleMs; }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // The row showing point (a name or an address, as rules name it), or -1.
    [[nodiscard]] int rowOf(const QString &point) const;
    [[nodiscard]] const WatchPointValue &valueAt(int row) const { return m_rows.at(row).value; }
    [[nodiscard]] bool hasValue(int row) const { return m_rows.at(row).known; }

private:
    struct ActiveRule {
        int rule = -1;
        WatchSeverity severity = WatchSeverity::Info;
        QString colour;
        QString message;
    };
    struct Row {
        WatchPointValue value;
        bool known = false;
        qint64 changedMs = 0;
        QList<ActiveRule> rules; // holding now, in the order they fired
    };
    [[nodiscard]] const ActiveRule *strongestRule(const Row &row) const;
    [[nodiscard]] QString referenceText(quint16 address) const;

    WatchDefinition m_watch;
    QList<Row> m_rows;
    qint64 m_lastSampleMs = 0;
};

} // namespace mbscope
