#include "fieldtreeview.h"

#include "fieldtreemodel.h"
#include "common/wraptextdelegate.h"

#include <QtGui/QPainter>
#include <QtWidgets/QHeaderView>

#include <array>

namespace mbscope {

namespace {

// The Problem column keeps at least this share of the width: it holds the sentences that matter.
constexpr double kProblemShare = 0.35;
// The Value column never shrinks below this many average characters to make that room.
constexpr int kMinValueChars = 24;

} // namespace

FieldTreeView::FieldTreeView(QWidget *parent)
    : QTreeView(parent)
{
    setAlternatingRowColors(true);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(QHeaderView::Interactive);
    // Offset and bytes read like a hex dump on the left; the hierarchy belongs to the names.
    setTreePosition(FieldTreeModel::FieldColumn);
    setItemDelegateForColumn(FieldTreeModel::ProblemColumn, new WrapTextDelegate(this, FieldTreeModel::ProblemColumn));
    // Wrapped rows change height with the Problem column's width; the layout is coalesced, so a
    // window resize or a refit costs one pass.
    connect(header(), &QHeaderView::sectionResized, this, [this](int logical, int, int) {
        if (logical == FieldTreeModel::ProblemColumn)
            scheduleDelayedItemsLayout();
    });
}

void FieldTreeView::setFieldModel(FieldTreeModel *model)
{
    setModel(model);
}

void FieldTreeView::showAllFields()
{
    expandAll();
    fitColumns();
}

// Widths are computed first and applied once, so the stretched Problem column (and the height of
// its wrapped rows) changes once per refit rather than once per column.
void FieldTreeView::fitColumns()
{
    if (!model())
        return;
    std::array<int, FieldTreeModel::ProblemColumn> widths{};
    int used = 0;
    for (int c = 0; c < FieldTreeModel::ProblemColumn; ++c) {
        widths[size_t(c)] = qMax(sizeHintForColumn(c), header()->isHidden() ? 0 : header()->sectionSizeHint(c));
        used += widths[size_t(c)];
    }
    // Room for problem messages only when there are some; a sound frame gives Value the width.
    const auto *fields = qobject_cast<const FieldTreeModel *>(model());
    const bool problems = fields && fields->dissection().fields.worstSeverity() != Severity::Ok;
    const int available = viewport()->width();
    const int problemWidth = problems ? int(available * kProblemShare)
                                      : header()->sectionSizeHint(FieldTreeModel::ProblemColumn);
    const int excess = used + problemWidth - available;
    if (excess > 0) {
        int &value = widths[FieldTreeModel::ValueColumn];
        const int minValue = fontMetrics().averageCharWidth() * kMinValueChars;
        value = qMax(qMin(value, minValue), value - excess);
    }
    for (int c = 0; c < FieldTreeModel::ProblemColumn; ++c) {
        if (columnWidth(c) != widths[size_t(c)])
            setColumnWidth(c, widths[size_t(c)]);
    }
}

void FieldTreeView::resizeEvent(QResizeEvent *event)
{
    QTreeView::resizeEvent(event);
    fitColumns();
}

// QTreeView paints the indentation in front of the tree column with the row's plain background,
// so a flagged field's tint would stop short of its name; carry the tint through unless selected.
void FieldTreeView::drawBranches(QPainter *painter, const QRect &rect, const QModelIndex &index) const
{
    if (!selectionModel() || !selectionModel()->isSelected(index)) {
        const QVariant tint = index.data(Qt::BackgroundRole);
        if (tint.isValid())
            painter->fillRect(rect, tint.value<QColor>());
    }
    QTreeView::drawBranches(painter, rect, index);
}

} // namespace mbscope
