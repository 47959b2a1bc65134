#pragma once

#include <QtWidgets/QStyledItemDelegate>

class QTreeView;

namespace mbscope {

// Lets one column of a tree view wrap its text onto as many lines as it needs. QTreeView can draw
// wrapped text but sizes rows from a one-line hint, so long texts get elided; this delegate
// measures the text against the column's current width. Row heights are cached by the view, so
// the view must lay its items out again when that column's width changes (FieldTreeView does).
// Used for problem messages, which must be read whole.
class WrapTextDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    WrapTextDelegate(QTreeView *view, int column);

    [[nodiscard]] QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;

private:
    QTreeView *m_view;
    int m_column;
};

} // namespace mbscope
