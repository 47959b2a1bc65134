#pragma once

#include <QtWidgets/QTreeView>

namespace mbscope {

class FieldTreeModel;

// The view of one dissection, shared by every place that shows a frame's fields. It reads like a
// hex dump on the left (offset, bytes) with the hierarchy in the Field column, wraps problem
// messages so they are read whole, and fits its columns to the frame shown while leaving the
// Problem column room.
class FieldTreeView : public QTreeView
{
    Q_OBJECT

public:
    explicit FieldTreeView(QWidget *parent = nullptr);

    void setFieldModel(FieldTreeModel *model);
    // Expands every field and sizes the columns to the frame shown; call after a new dissection.
    void showAllFields();

protected:
    void drawBranches(QPainter *painter, const QRect &rect, const QModelIndex &index) const override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void fitColumns();
};

} // namespace mbscope
