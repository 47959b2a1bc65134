#include "wraptextdelegate.h"

#include <QtWidgets/QApplication>
#include <QtWidgets/QStyle>
#include <QtWidgets/QTreeView>

namespace mbscope {

WrapTextDelegate::WrapTextDelegate(QTreeView *view, int column)
    : QStyledItemDelegate(view)
    , m_view(view)
    , m_column(column)
{
    view->setWordWrap(true);
    view->setUniformRowHeights(false);
}

QSize WrapTextDelegate::sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const
{
    QSize hint = QStyledItemDelegate::sizeHint(option, index);
    if (index.column() != m_column)
        return hint;
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    if (opt.text.isEmpty())
        return hint;
    const QStyle *style = opt.widget ? opt.widget->style() : QApplication::style();
    // The same margin QCommonStyle leaves on each side of an item's text.
    const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, opt.widget) + 1;
    int width = m_view->columnWidth(m_column) - 2 * margin;
    if (!opt.icon.isNull())
        width -= opt.decorationSize.width() + 2 * margin;
    if (width <= 0)
        return hint;
    const QRect text = opt.fontMetrics.boundingRect(QRect(0, 0, width, 1 << 20),
                                                    Qt::AlignLeft | Qt::TextWordWrap, opt.text);
    const int oneLine = opt.fontMetrics.height();
    hint.setHeight(qMax(hint.height(), hint.height() - oneLine + text.height()));
    return hint;
}

} // namespace mbscope
