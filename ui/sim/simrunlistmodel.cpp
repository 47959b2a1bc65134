#include "simrunlistmodel.h"

#include "sim/simulatorhost.h"

#include <QtCore/QStringList>

namespace mbscope {

namespace {

bool isRequest(const SimLogEntry &entry)
{
    using V = SimLogEntry::Verdict;
    return entry.verdict != V::ConnectionOpened && entry.verdict != V::ConnectionClosed
           && entry.verdict != V::ConnectionRefused && entry.verdict != V::Garbage;
}

} // namespace

SimRunListModel::SimRunListModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void SimRunListModel::addHost(SimulatorHost *host, const QString &label, bool builtIn)
{
    if (!host || rowOf(host) >= 0)
        return;
    QStringList urls;
    for (const LinkUrl &url : host->boundUrls())
        urls << url.toString();
    const int row = int(m_runs.size());
    beginInsertRows({}, row, row);
    m_runs.append(Run{host, label, urls.join(QStringLiteral(", ")), builtIn, 0, 0});
    endInsertRows();
    connect(host, &SimulatorHost::stopped, this, [this, host] { removeHost(host); });
    connect(host, &QObject::destroyed, this, [this] {
        // The QPointer is null by now: drop every row whose host is gone.
        for (int gone = int(m_runs.size()) - 1; gone >= 0; --gone) {
            if (!m_runs[gone].host) {
                beginRemoveRows({}, gone, gone);
                m_runs.removeAt(gone);
                endRemoveRows();
            }
        }
    });
}

void SimRunListModel::removeHost(SimulatorHost *host)
{
    const int row = rowOf(host);
    if (row < 0)
        return;
    disconnect(host, nullptr, this, nullptr);
    beginRemoveRows({}, row, row);
    m_runs.removeAt(row);
    endRemoveRows();
}

SimulatorHost *SimRunListModel::hostAt(int row) const
{
    return row >= 0 && row < m_runs.size() ? m_runs[row].host.data() : nullptr;
}

int SimRunListModel::rowOf(const SimulatorHost *host) const
{
    for (int row = 0; row < m_runs.size(); ++row) {
        if (m_runs[row].host == host)
            return row;
    }
    return -1;
}

bool SimRunListModel::isBuiltIn(int row) const
{
    return row >= 0 && row < m_runs.size() && m_runs[row].builtIn;
}

void SimRunListModel::countRecords(SimulatorHost *host, const QList<SimTrafficRecord> &records)
{
    const int row = rowOf(host);
    if (row < 0)
        return;
    Run &run = m_runs[row];
    for (const SimTrafficRecord &record : records) {
        if (isRequest(record.entry))
            ++run.requests;
        if (record.isFaulted())
            ++run.faulted;
    }
    Q_EMIT dataChanged(index(row, RequestsColumn), index(row, FaultedColumn));
}

int SimRunListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_runs.size());
}

int SimRunListModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SimRunListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Run &run = m_runs[index.row()];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case ProfileColumn: return run.builtIn ? tr("%1 (built-in, first run)").arg(run.label) : run.label;
        case EndpointColumn: return run.endpoints;
        case RequestsColumn: return QString::number(run.requests);
        case FaultedColumn: return QString::number(run.faulted);
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole && index.column() == ProfileColumn && run.host)
        return run.host->profile().description;
    if (role == Qt::TextAlignmentRole && (index.column() == RequestsColumn || index.column() == FaultedColumn))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant SimRunListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case ProfileColumn: return tr("Profile");
    case EndpointColumn: return tr("Listening on");
    case RequestsColumn: return tr("Requests");
    case FaultedColumn: return tr("Faulted");
    default: return {};
    }
}

} // namespace mbscope
