#pragma once

#include "conformance/conformancecheck.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtGui/QColor>

namespace mbscope {

// The Conformance window's scorecard: a row per check as the battery decides it (verdict
// coloured, id and title, clause, the sentence, the request sent and the answer as hex).
class ConformanceResultModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { VerdictColumn, CheckColumn, ClauseColumn, SentenceColumn, RequestColumn, AnswerColumn, ColumnCount };

    explicit ConformanceResultModel(QObject *parent = nullptr);

    void clear();
    void append(const CheckResult &result);
    [[nodiscard]] const QList<CheckResult> &results() const { return m_results; }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The row's background: red for a mandatory failure or an error, amber for a recommended
    // one, blue for a measurement, green for a pass, none for a skipped check.
    [[nodiscard]] static QColor verdictColor(const CheckResult &result);

private:
    QList<CheckResult> m_results;
};

} // namespace mbscope
