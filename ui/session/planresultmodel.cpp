#include "planresultmodel.h"

#include "common/severitystyle.h"

#include <QtCore/QRegularExpression>
#include <QtGui/QBrush>
#include <QtGui/QColor>

namespace mbscope {

PlanResultModel::PlanResultModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void PlanResultModel::reset(const SessionDocument &document)
{
    beginResetModel();
    m_document = document;
    m_steps.clear();
    m_expected.clear();
    endResetModel();
}

void PlanResultModel::appendStep(const StepResult &step)
{
    const int at = int(m_steps.size());
    beginInsertRows({}, at, at);
    m_steps.append(step);
    const PlanStep *planStep = stepAt(m_document, step.path);
    m_expected.append(planStep ? expectedText(*planStep) : QString());
    endInsertRows();
}

QString PlanResultModel::outcomeText(StepResult::Outcome outcome)
{
    switch (outcome) {
    case StepResult::Outcome::Passed:
        return tr("PASS");
    case StepResult::Outcome::Failed:
        return tr("FAIL");
    case StepResult::Outcome::Error:
        return tr("ERROR");
    case StepResult::Outcome::Skipped:
        return tr("SKIP");
    }
    return QString();
}

const PlanStep *PlanResultModel::stepAt(const SessionDocument &document, const QString &path)
{
    static const QRegularExpression index(QStringLiteral("\\[(\\d+)\\]"));
    const std::vector<PlanStep> *steps = &document.plan;
    const PlanStep *step = nullptr;
    QRegularExpressionMatchIterator it = index.globalMatch(path);
    while (it.hasNext()) {
        const std::size_t i = it.next().captured(1).toULongLong();
        if (!steps || i >= steps->size())
            return nullptr;
        step = &(*steps)[i];
        steps = &step->steps;
    }
    return step;
}

QString PlanResultModel::expectedText(const PlanStep &step)
{
    switch (step.kind) {
    case PlanStep::Kind::Send:
    case PlanStep::Kind::Expect: {
        const StepExpectation &e = step.expect;
        if (e.noAnswer)
            return tr("no answer");
        QStringList parts;
        if (e.bytes)
            parts.append(tr("answer %1").arg(*e.bytes));
        for (const FieldExpectation &field : e.fields)
            parts.append(tr("%1 = %2").arg(field.selector, field.expectedText()));
        if (e.exception)
            parts.append(tr("exception 0x%1").arg(QStringLiteral("%1").arg(*e.exception, 2, 16, QLatin1Char('0')).toUpper()));
        if (parts.isEmpty())
            return step.kind == PlanStep::Kind::Send ? tr("any answer") : QString();
        return parts.join(QStringLiteral(", "));
    }
    case PlanStep::Kind::Poll: {
        QStringList bounds;
        for (const PollBound &bound : step.bounds)
            bounds.append(bound.text);
        return bounds.isEmpty() ? tr("the poll runs") : bounds.join(QStringLiteral(", "));
    }
    case PlanStep::Kind::Wait:
        return tr("waits %1 ms").arg(step.waitMs);
    case PlanStep::Kind::Repeat:
        return tr("repeats, times: %1").arg(step.times);
    }
    return QString();
}

int PlanResultModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_steps.size());
}

int PlanResultModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant PlanResultModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const StepResult &step = m_steps.at(index.row());
    const bool failed = step.outcome == StepResult::Outcome::Failed || step.outcome == StepResult::Outcome::Error;
    if (role == Qt::DisplayRole || role == Qt::ToolTipRole) {
        switch (index.column()) {
        case OutcomeColumn:
            return outcomeText(step.outcome);
        case StepColumn:
            return role == Qt::ToolTipRole ? step.path : step.name;
        case ExpectedColumn:
            return m_expected.at(index.row());
        case CameColumn:
            return step.detail;
        case WhyColumn:
            // A passed step's reasons say what was checked; only a failure needs a why.
            return failed ? step.reasons.join(role == Qt::ToolTipRole ? QStringLiteral("\n") : QStringLiteral("; ")) : QString();
        case TimeColumn:
            return QString::number(double(step.elapsedNs) / 1e6, 'f', 1);
        default:
            return {};
        }
    }
    if (role == Qt::ForegroundRole && index.column() == OutcomeColumn) {
        switch (step.outcome) {
        case StepResult::Outcome::Passed:
            return QBrush(SeverityStyle::goodColor());
        case StepResult::Outcome::Failed:
        case StepResult::Outcome::Error:
            return QBrush(SeverityStyle::textColor(Severity::Error));
        case StepResult::Outcome::Skipped:
            return QBrush(SeverityStyle::mutedColor());
        }
    }
    if (role == Qt::TextAlignmentRole && index.column() == TimeColumn)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant PlanResultModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case OutcomeColumn:
        return tr("Result");
    case StepColumn:
        return tr("Step");
    case ExpectedColumn:
        return tr("Expected");
    case CameColumn:
        return tr("What came");
    case WhyColumn:
        return tr("Why it failed");
    case TimeColumn:
        return tr("ms");
    default:
        return {};
    }
}

} // namespace mbscope
