#include "conformanceresultmodel.h"

#include "common/severitystyle.h"
#include "common/theme.h"
#include "conformance/conformancejudge.h"
#include "conformance/conformanceresult.h"

#include <QtGui/QColor>

namespace mbscope {

ConformanceResultModel::ConformanceResultModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void ConformanceResultModel::clear()
{
    beginResetModel();
    m_results.clear();
    endResetModel();
}

void ConformanceResultModel::append(const CheckResult &result)
{
    const int row = int(m_results.size());
    beginInsertRows({}, row, row);
    m_results.append(result);
    endInsertRows();
}

int ConformanceResultModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_results.size());
}

int ConformanceResultModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QColor ConformanceResultModel::verdictColor(const CheckResult &r)
{
    switch (r.verdict) {
    case CheckVerdict::Passed:
        if (r.level == CheckLevel::Informational)
            return SeverityStyle::backgroundColor(Severity::Info);
        return Theme::isDark() ? QColor(0x1f, 0x4a, 0x2a) : QColor(0xd8, 0xf0, 0xd8);
    case CheckVerdict::Failed:
        return SeverityStyle::backgroundColor(r.level == CheckLevel::Mandatory ? Severity::Error : Severity::Warning);
    case CheckVerdict::Error:
        return SeverityStyle::backgroundColor(Severity::Error);
    case CheckVerdict::Skipped:
        break;
    }
    return {};
}

QVariant ConformanceResultModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_results.size())
        return {};
    const CheckResult &r = m_results.at(index.row());
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case VerdictColumn: return QString::fromLatin1(ConformanceResult::label(r));
        case CheckColumn: return QStringLiteral("%1: %2").arg(r.id, r.title);
        case ClauseColumn: return r.clause;
        case SentenceColumn: return r.sentence;
        case RequestColumn: return ConformanceJudge::hex(r.request);
        case AnswerColumn: return r.answer.isEmpty() && !r.request.isEmpty() ? tr("(none)") : ConformanceJudge::hex(r.answer);
        default: break;
        }
    } else if (role == Qt::ToolTipRole) {
        if (index.column() == VerdictColumn)
            return tr("%1, %2").arg(QLatin1String(checkVerdictName(r.verdict)), QLatin1String(checkLevelName(r.level)));
        if (index.column() == SentenceColumn || index.column() == CheckColumn)
            return r.sentence;
    } else if (role == Qt::BackgroundRole && index.column() == VerdictColumn) {
        const QColor c = verdictColor(r);
        if (c.isValid())
            return c;
    } else if (role == Qt::UserRole) {
        return QLatin1String(checkVerdictName(r.verdict));
    }
    return {};
}

QVariant ConformanceResultModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case VerdictColumn: return tr("Verdict");
    case CheckColumn: return tr("Check");
    case ClauseColumn: return tr("Clause");
    case SentenceColumn: return tr("Why");
    case RequestColumn: return tr("Request");
    case AnswerColumn: return tr("Answer");
    default: break;
    }
    return {};
}

} // namespace mbscope
