#pragma once

#include "session/planresult.h"
#include "session/sessiondocument.h"

#include <QtCore/QAbstractTableModel>

namespace mbscope {

// A test plan's run, one row per step result (a repeated step once per repetition), as it goes:
// pass or fail, the step, what it expected (read from the plan step the result's path names),
// what came (the exchange), and why it failed (the runner's reasons).
class PlanResultModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { OutcomeColumn, StepColumn, ExpectedColumn, CameColumn, WhyColumn, TimeColumn, ColumnCount };

    explicit PlanResultModel(QObject *parent = nullptr);

    // A new run of document's plan: clears the rows.
    void reset(const SessionDocument &document);
    void appendStep(const StepResult &step);
    [[nodiscard]] const QList<StepResult> &steps() const { return m_steps; }

    // "PASS", "FAIL", "ERROR", "SKIP"
    [[nodiscard]] static QString outcomeText(StepResult::Outcome outcome);
    // What a step expects, in words: "answer 01 03 02 00 0A …, modbus.register_value@0x0079 = 1050",
    // "exception 0x02", "no answer", "p95 < 20 ms, timeouts == 0", "waits 200 ms".
    [[nodiscard]] static QString expectedText(const PlanStep &step);
    // The plan step a result's path names ("plan[4].steps[1]"); null when there is none.
    [[nodiscard]] static const PlanStep *stepAt(const SessionDocument &document, const QString &path);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    SessionDocument m_document;
    QList<StepResult> m_steps;
    QStringList m_expected; // per row, made when the row came
};

} // namespace mbscope
