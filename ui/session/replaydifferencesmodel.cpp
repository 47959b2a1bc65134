#include "replaydifferencesmodel.h"

#include "common/severitystyle.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"
#include "replay/replayscript.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>

#include <cstdlib>

namespace mbscope {

namespace {

QString latencyText(const Transaction &t)
{
    const qint64 ns = t.latencyNs();
    if (ns < 0 || t.response.isEmpty())
        return QString();
    return QString::number(double(ns) / 1e6, 'f', 3);
}

bool timedOut(const Transaction &t)
{
    return t.status == TransactionStatus::Timeout || t.status == TransactionStatus::LinkError;
}

} // namespace

ReplayDifferencesModel::ReplayDifferencesModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

ReplayDifferencesModel::~ReplayDifferencesModel() = default;

bool ReplayDifferencesModel::isLatencyChange(qint64 recordedNs, qint64 nowNs)
{
    if (recordedNs < 0 || nowNs < 0)
        return false;
    constexpr qint64 kSlackNs = 10'000'000;
    if (std::llabs(nowNs - recordedNs) < kSlackNs)
        return false;
    return nowNs > 2 * recordedNs || recordedNs > 2 * nowNs;
}

ReplayDifferencesModel::Kind ReplayDifferencesModel::classify(const ReplayOutcome &outcome, const Transaction &recorded,
                                                              Framing recordedFraming, Framing nowFraming)
{
    const Transaction &now = outcome.replayed;
    using Verdict = AnswerComparison::Verdict;
    switch (outcome.comparison.verdict) {
    case Verdict::MissingAnswer:
        return Kind::Timeout;
    case Verdict::OutcomeDiffers:
        if (timedOut(recorded) || timedOut(now))
            return Kind::Timeout;
        if (recorded.status == TransactionStatus::Exception || now.status == TransactionStatus::Exception)
            return Kind::Exception;
        return Kind::Outcome;
    case Verdict::ValuesDiffer:
        return Kind::Values;
    case Verdict::Match:
        break;
    }
    if (!recorded.response.isEmpty() && !now.response.isEmpty()
        && AduBuilder::parse(recorded.response, recordedFraming).pdu != AduBuilder::parse(now.response, nowFraming).pdu)
        return Kind::Bytes;
    if (!recorded.response.isEmpty() && !now.response.isEmpty() && isLatencyChange(recorded.latencyNs(), now.latencyNs()))
        return Kind::Latency;
    return Kind::Same;
}

QString ReplayDifferencesModel::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Same:
        return tr("the same");
    case Kind::Values:
        return tr("values");
    case Kind::Bytes:
        return tr("bytes");
    case Kind::Exception:
        return tr("exception");
    case Kind::Outcome:
        return tr("outcome");
    case Kind::Timeout:
        return tr("timeout");
    case Kind::Latency:
        return tr("latency");
    }
    return QString();
}

void ReplayDifferencesModel::reset(std::shared_ptr<const ReplayScript> script, Framing targetFraming)
{
    beginResetModel();
    m_script = std::move(script);
    m_targetFraming = targetFraming;
    m_rows.clear();
    m_shown.clear();
    m_counts.fill(0);
    endResetModel();
}

void ReplayDifferencesModel::appendOutcome(const ReplayOutcome &outcome)
{
    if (!m_script || outcome.index < 0 || outcome.index >= m_script->size())
        return;
    const ReplayExchange &recorded = m_script->exchanges().at(std::size_t(outcome.index));
    Row row{outcome, classify(outcome, recorded.recorded, recorded.framing, m_targetFraming)};
    ++m_counts[std::size_t(row.kind)];
    const bool shown = m_showMatches || row.kind != Kind::Same;
    m_rows.push_back(std::move(row));
    if (shown) {
        const int at = int(m_shown.size());
        beginInsertRows({}, at, at);
        m_shown.push_back(qsizetype(m_rows.size()) - 1);
        endInsertRows();
    }
}

void ReplayDifferencesModel::setShowMatches(bool show)
{
    if (show == m_showMatches)
        return;
    beginResetModel();
    m_showMatches = show;
    rebuildShown();
    endResetModel();
}

void ReplayDifferencesModel::rebuildShown()
{
    m_shown.clear();
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        if (m_showMatches || m_rows[i].kind != Kind::Same)
            m_shown.push_back(qsizetype(i));
    }
}

ReplayDifferencesModel::Kind ReplayDifferencesModel::kindAt(int row) const
{
    return row >= 0 && row < rowCount() ? shownRow(row).kind : Kind::Same;
}

QString ReplayDifferencesModel::countsText() const
{
    QStringList parts;
    for (std::size_t k = 0; k < kKindCount; ++k) {
        if (m_counts[k] > 0)
            parts.append(tr("%1: %2", "what differs: how many").arg(kindName(Kind(k))).arg(m_counts[k]));
    }
    if (parts.isEmpty())
        return tr("No answers replayed yet.");
    return tr("Answers replayed: %1, differing: %2 (%3).")
        .arg(replayed())
        .arg(differed())
        .arg(parts.join(QStringLiteral(", ")));
}

int ReplayDifferencesModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_shown.size());
}

int ReplayDifferencesModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ReplayDifferencesModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid) || !m_script)
        return {};
    const Row &row = shownRow(index.row());
    const ReplayExchange &recorded = m_script->exchanges().at(std::size_t(row.outcome.index));
    const Transaction &now = row.outcome.replayed;
    const auto answerText = [](const Transaction &t) {
        return t.response.isEmpty() ? AnswerComparison::describeOutcome(t) : HexText::format(t.response);
    };
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case IndexColumn:
            return int(row.outcome.index + 1);
        case RequestColumn:
            return HexText::format(recorded.recorded.request);
        case RecordedColumn:
            return answerText(recorded.recorded);
        case NowColumn:
            return answerText(now);
        case KindColumn:
            return kindName(row.kind);
        case DifferencesColumn:
            return row.outcome.comparison.differences.join(QStringLiteral("; "));
        case RecordedLatencyColumn:
            return latencyText(recorded.recorded);
        case NowLatencyColumn:
            return latencyText(now);
        default:
            return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        if (index.column() == DifferencesColumn && !row.outcome.comparison.differences.isEmpty())
            return row.outcome.comparison.differences.join(QLatin1Char('\n'));
        if (index.column() == NowColumn && !now.problem.isEmpty())
            return now.problem;
        return {};
    }
    if (role == Qt::ForegroundRole && index.column() == KindColumn && row.kind != Kind::Same)
        return QBrush(SeverityStyle::textColor(row.kind == Kind::Latency ? Severity::Warning : Severity::Error));
    if (role == Qt::TextAlignmentRole && (index.column() == IndexColumn || index.column() >= RecordedLatencyColumn))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant ReplayDifferencesModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case IndexColumn:
        return tr("#");
    case RequestColumn:
        return tr("Request");
    case RecordedColumn:
        return tr("Recorded answer");
    case NowColumn:
        return tr("New answer");
    case KindColumn:
        return tr("What differs");
    case DifferencesColumn:
        return tr("Differences");
    case RecordedLatencyColumn:
        return tr("Recorded ms");
    case NowLatencyColumn:
        return tr("Now ms");
    default:
        return {};
    }
}

} // namespace mbscope
