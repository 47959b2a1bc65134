#pragma once

#include <QtWidgets/QTableView>

namespace mbscope {

// A table whose Tab and Shift+Tab go from one editable cell to the next (row by row, hidden
// columns skipped) instead of stopping on every read-only one (the address, the reference,
// the name); past the last editable cell Tab leaves the table, as from any other field.
// The arrow keys still visit every cell.
class EditableCellsView : public QTableView
{
    Q_OBJECT

public:
    explicit EditableCellsView(QWidget *parent = nullptr);

protected:
    QModelIndex moveCursor(CursorAction cursorAction, Qt::KeyboardModifiers modifiers) override;
};

} // namespace mbscope
