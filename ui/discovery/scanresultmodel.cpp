#include "scanresultmodel.h"

#include "common/severitystyle.h"

#include "protocol/functioncode.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>
#include <QtGui/QFont>

namespace mbscope {

ScanResultModel::ScanResultModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void ScanResultModel::clear()
{
    beginResetModel();
    m_probes.clear();
    endResetModel();
}

void ScanResultModel::append(const UnitProbe &probe)
{
    const int row = int(m_probes.size());
    beginInsertRows({}, row, row);
    m_probes.append(probe);
    endInsertRows();
}

QString ScanResultModel::kindText(UnitProbeKind kind)
{
    switch (kind) {
    case UnitProbeKind::Answers: return tr("answers");
    case UnitProbeKind::Exception: return tr("exception");
    case UnitProbeKind::GatewayPathUnavailable: return tr("gateway: no path (0A)");
    case UnitProbeKind::GatewayTargetFailed: return tr("gateway: no answer behind it (0B)");
    case UnitProbeKind::Silent: return tr("silent");
    case UnitProbeKind::WrongUnit: return tr("answered with another id");
    case UnitProbeKind::Garbage: return tr("garbage");
    case UnitProbeKind::Echo: return tr("echo of the request");
    case UnitProbeKind::LinkError: return tr("link error");
    }
    return {};
}

QString ScanResultModel::detailText(const UnitProbe &probe)
{
    switch (probe.kind) {
    case UnitProbeKind::Exception:
    case UnitProbeKind::GatewayPathUnavailable:
    case UnitProbeKind::GatewayTargetFailed:
        return tr("exception %1: %2")
            .arg(QStringLiteral("%1").arg(probe.exceptionCode, 2, 16, QLatin1Char('0')).toUpper(),
                 QString::fromLatin1(exceptionName(probe.exceptionCode)));
    case UnitProbeKind::WrongUnit: return tr("the answer carried unit %1").arg(probe.answeredUnit);
    case UnitProbeKind::Garbage:
    case UnitProbeKind::LinkError: return probe.problem;
    default: return {};
    }
}

int ScanResultModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_probes.size());
}

int ScanResultModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ScanResultModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_probes.size())
        return {};
    const UnitProbe &p = m_probes.at(index.row());
    if (role == ProbeRole)
        return QVariant::fromValue(p);
    if (role == Qt::FontRole && p.isPresent()) {
        QFont bold;
        bold.setBold(true);
        return bold;
    }
    if (role == Qt::ForegroundRole && (p.kind == UnitProbeKind::Silent || p.kind == UnitProbeKind::GatewayTargetFailed))
        return QBrush(SeverityStyle::mutedColor());
    if (role == Qt::TextAlignmentRole && (index.column() == UnitColumn || index.column() == LatencyColumn))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case UnitColumn: return int(p.unit);
    case ResultColumn: return kindText(p.kind);
    case LatencyColumn:
        return p.latencyNs >= 0 ? tr("%1 ms").arg(QString::number(double(p.latencyNs) / 1e6, 'f', 2)) : QString();
    case DetailColumn: return detailText(p);
    default: return {};
    }
}

QVariant ScanResultModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case UnitColumn: return tr("Unit");
    case ResultColumn: return tr("Result");
    case LatencyColumn: return tr("Latency");
    case DetailColumn: return tr("Detail");
    default: return {};
    }
}

} // namespace mbscope
