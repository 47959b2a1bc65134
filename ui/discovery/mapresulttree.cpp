#include "mapresulttree.h"

#include "protocol/hextext.h"

#include <QtWidgets/QHeaderView>

namespace mbscope {

namespace {

QString hex(int value, int digits)
{
    return QStringLiteral("%1").arg(value, digits, 16, QLatin1Char('0')).toUpper();
}

// "1050 0 0 0 250 …": the first values of a block, enough to recognise it.
QString firstValues(const MapBlock &block)
{
    constexpr int shown = 8;
    QStringList parts;
    for (int i = 0; i < qMin(shown, block.count()); ++i)
        parts.append(QString::number(block.values.at(i)));
    if (block.count() > shown)
        parts.append(QStringLiteral("\u2026"));
    return parts.join(QLatin1Char(' '));
}

QString functionLabel(const FunctionSupport &s)
{
    QString label = hex(s.function, 2);
    if (s.subFunction >= 0)
        label += QLatin1Char('/') + hex(s.subFunction, s.function == 0x08 ? 4 : 2);
    return label;
}

QString answerText(const FunctionSupport &s)
{
    switch (s.answer) {
    case FunctionSupport::Answer::Answers: return MapResultTree::tr("answers");
    case FunctionSupport::Answer::Exception:
        return s.exceptionCode == 0x01 ? MapResultTree::tr("exception 01: not supported")
             : s.fromGateway()         ? MapResultTree::tr("exception %1 from a gateway: no device").arg(hex(s.exceptionCode, 2))
                                       : MapResultTree::tr("exception %1: known, refused").arg(hex(s.exceptionCode, 2));
    case FunctionSupport::Answer::Silent: return MapResultTree::tr("silent");
    case FunctionSupport::Answer::NotProbed: return MapResultTree::tr("not asked");
    }
    return {};
}

} // namespace

MapResultTree::MapResultTree(QWidget *parent)
    : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("mapResults"));
    setColumnCount(ColumnCount);
    setHeaderLabels({tr("Table or function"), tr("Found"), tr("Detail")});
    setRootIsDecorated(true);
    setUniformRowHeights(true);
    header()->setStretchLastSection(true);
    setColumnWidth(ItemColumn, 220);
    setColumnWidth(FindingColumn, 200);
}

QString MapResultTree::tableName(quint8 function)
{
    switch (function) {
    case 1: return tr("01 Coils");
    case 2: return tr("02 Discrete inputs");
    case 3: return tr("03 Holding registers");
    case 4: return tr("04 Input registers");
    default: return hex(function, 2);
    }
}

int MapResultTree::addressCount(const RegisterMap &map)
{
    int n = 0;
    for (const TableMap &t : map.tables) {
        for (const MapBlock &b : t.blocks)
            n += b.count();
    }
    return n;
}

void MapResultTree::showMap(const RegisterMap &map)
{
    clear();
    for (const TableMap &t : map.tables) {
        auto *table = new QTreeWidgetItem(this);
        table->setText(ItemColumn, tableName(t.function));
        table->setText(DetailColumn, tr("addresses %1-%2 searched, %n request(s)", nullptr, t.requests)
                                         .arg(t.searchedFirst)
                                         .arg(t.searchedLast));
        if (t.gatewayException != 0) {
            table->setText(FindingColumn, tr("no device: exception %1 from a gateway").arg(hex(t.gatewayException, 2)));
            continue;
        }
        if (!t.supported) {
            table->setText(FindingColumn, tr("not answered (exception 01 or silence)"));
            continue;
        }
        table->setText(FindingColumn, t.blocks.isEmpty() ? tr("no address answered")
                                                         : tr("%n block(s)", nullptr, int(t.blocks.size())));
        if (t.maxQuantity > 0)
            table->setText(FindingColumn, table->text(FindingColumn) + tr(", largest read %1").arg(t.maxQuantity));
        for (const MapBlock &b : t.blocks) {
            auto *block = new QTreeWidgetItem(table);
            block->setText(ItemColumn, tr("%1-%2 (0x%3-0x%4)").arg(b.address).arg(b.last()).arg(hex(b.address, 4), hex(b.last(), 4)));
            block->setText(FindingColumn, tr("%n address(es)", nullptr, b.count()));
            block->setText(DetailColumn, firstValues(b));
        }
        table->setExpanded(true);
    }
    if (!map.functions.isEmpty()) {
        auto *functions = new QTreeWidgetItem(this);
        functions->setText(ItemColumn, tr("Optional functions"));
        int known = 0;
        for (const FunctionSupport &s : map.functions) {
            auto *row = new QTreeWidgetItem(functions);
            row->setText(ItemColumn, functionLabel(s));
            row->setText(FindingColumn, answerText(s));
            row->setText(DetailColumn, s.note);
            known += s.known() ? 1 : 0;
        }
        functions->setText(FindingColumn, tr("%1 of %2 known").arg(known).arg(map.functions.size()));
        functions->setExpanded(true);
    }
    if (map.exceptionStatus >= 0) {
        auto *status = new QTreeWidgetItem(this);
        status->setText(ItemColumn, tr("Exception status (07)"));
        status->setText(FindingColumn, QStringLiteral("0x") + hex(map.exceptionStatus, 2));
    }
    if (!map.serverIdData.isEmpty()) {
        auto *id = new QTreeWidgetItem(this);
        id->setText(ItemColumn, tr("Server id (11)"));
        id->setText(FindingColumn, HexText::format(map.serverIdData));
    }
}

} // namespace mbscope
