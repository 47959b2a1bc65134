#include "editablecellsview.h"

#include <QtWidgets/QHeaderView>

namespace mbscope {

EditableCellsView::EditableCellsView(QWidget *parent)
    : QTableView(parent)
{
}

QModelIndex EditableCellsView::moveCursor(CursorAction cursorAction, Qt::KeyboardModifiers modifiers)
{
    if ((cursorAction != MoveNext && cursorAction != MovePrevious) || !model())
        return QTableView::moveCursor(cursorAction, modifiers);
    const int rows = model()->rowCount(rootIndex());
    const int columns = model()->columnCount(rootIndex());
    if (rows == 0 || columns == 0)
        return {};
    const int step = cursorAction == MoveNext ? 1 : -1;
    const QModelIndex current = currentIndex();
    // Cells in the order they are shown: visual columns, row by row.
    int row = current.isValid() ? current.row() : (step > 0 ? 0 : rows - 1);
    int visual = current.isValid() ? horizontalHeader()->visualIndex(current.column()) : (step > 0 ? -1 : columns);
    for (int tries = 0; tries < rows * columns; ++tries) {
        visual += step;
        if (visual >= columns) {
            visual = 0;
            ++row;
        } else if (visual < 0) {
            visual = columns - 1;
            --row;
        }
        if (row < 0 || row >= rows)
            return {}; // past the last (or before the first) editable cell: the focus moves on
        const int logical = horizontalHeader()->logicalIndex(visual);
        if (isColumnHidden(logical) || isRowHidden(row))
            continue;
        const QModelIndex index = model()->index(row, logical, rootIndex());
        if (model()->flags(index) & Qt::ItemIsEditable)
            return index;
    }
    return {};
}

} // namespace mbscope
