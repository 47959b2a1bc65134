#include "watchpointtable.h"

#include <QtWidgets/QHeaderView>

namespace mbscope {

WatchPointTable::WatchPointTable(QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setObjectName(QStringLiteral("watchPoints"));
    setHorizontalHeaderLabels({tr("Address"), tr("Name"), tr("Format"), tr("Unit"), tr("Scale"), tr("Offset"), tr("Writable")});
    horizontalHeader()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    verticalHeader()->hide();
    setToolTip(tr("Address: the PDU address (0-based; 0x hex allowed). Format: u16, i16, u32-abcd, f32-cdab, ... "
                  "Value = raw x scale + offset."));
}

void WatchPointTable::setRow(int row, const WatchPoint &point)
{
    setItem(row, AddressColumn, new QTableWidgetItem(QString::number(point.address)));
    setItem(row, NameColumn, new QTableWidgetItem(point.name));
    setItem(row, FormatColumn, new QTableWidgetItem(point.format.name()));
    setItem(row, UnitColumn, new QTableWidgetItem(point.unit));
    setItem(row, ScaleColumn, new QTableWidgetItem(QString::number(point.scale)));
    setItem(row, OffsetColumn, new QTableWidgetItem(QString::number(point.offset)));
    auto *writable = new QTableWidgetItem;
    writable->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
    writable->setCheckState(point.writable ? Qt::Checked : Qt::Unchecked);
    setItem(row, WritableColumn, writable);
}

void WatchPointTable::setPoints(const QList<WatchPoint> &points)
{
    m_original = points;
    setRowCount(0);
    setRowCount(int(points.size()));
    for (int row = 0; row < points.size(); ++row)
        setRow(row, points.at(row));
}

void WatchPointTable::addPoint(quint16 address)
{
    WatchPoint point;
    point.address = address;
    const int row = rowCount();
    insertRow(row);
    setRow(row, point);
    setCurrentCell(row, NameColumn);
    editItem(item(row, NameColumn));
}

void WatchPointTable::removeCurrent()
{
    if (currentRow() >= 0)
        removeRow(currentRow());
}

QList<WatchPoint> WatchPointTable::points(QStringList *problems) const
{
    QList<WatchPoint> points;
    auto text = [this](int row, int column) { return item(row, column) ? item(row, column)->text().trimmed() : QString(); };
    for (int row = 0; row < rowCount(); ++row) {
        const QString where = tr("point %1").arg(row + 1);
        WatchPoint point;
        const QString address = text(row, AddressColumn);
        bool ok = false;
        const uint value = address.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? address.mid(2).toUInt(&ok, 16)
                                                                                         : address.toUInt(&ok, 10);
        if (!ok || value > 0xffff) {
            problems->append(tr("%1: address '%2' is not 0 to 65535").arg(where, address));
            continue;
        }
        point.address = quint16(value);
        for (const WatchPoint &original : m_original) {
            if (original.address == point.address)
                point.bitFields = original.bitFields, point.description = original.description;
        }
        point.name = text(row, NameColumn);
        const QString formatText = text(row, FormatColumn);
        if (!formatText.isEmpty()) {
            const RegisterFormatResult format = RegisterFormat::parse(formatText);
            if (!format.error.isEmpty()) {
                problems->append(QStringLiteral("%1: %2").arg(where, format.error));
                continue;
            }
            point.format = format.format;
        }
        point.unit = text(row, UnitColumn);
        const double scale = text(row, ScaleColumn).isEmpty() ? 1 : text(row, ScaleColumn).toDouble(&ok);
        if (!ok || scale == 0) {
            problems->append(tr("%1: scale '%2' is not a number other than 0").arg(where, text(row, ScaleColumn)));
            continue;
        }
        point.scale = scale;
        ok = true;
        point.offset = text(row, OffsetColumn).isEmpty() ? 0 : text(row, OffsetColumn).toDouble(&ok);
        if (!ok) {
            problems->append(tr("%1: offset '%2' is not a number").arg(where, text(row, OffsetColumn)));
            continue;
        }
        point.writable = item(row, WritableColumn) && item(row, WritableColumn)->checkState() == Qt::Checked;
        points.append(point);
    }
    std::sort(points.begin(), points.end(), [](const WatchPoint &a, const WatchPoint &b) { return a.address < b.address; });
    return points;
}

} // namespace mbscope
