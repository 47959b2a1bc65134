#include "frameinspector.h"

#include "fieldlocator.h"
#include "fieldtreemodel.h"
#include "fieldtreeview.h"
#include "hexview.h"
#include "common/severitystyle.h"

#include <QtWidgets/QLabel>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

// Room beyond the hint goes to the tree: its rows carry names, values and problems, while the hex
// view lays out 16, 8 or 4 bytes a line in what it gets.
constexpr int kTreeStretch = 1;
constexpr int kHexStretch = 0;
// The hex view's share of the width, between its narrowest (4 bytes a line) and widest (16).
constexpr int kHexSharePercent = 40;

} // namespace

FrameInspector::FrameInspector(QWidget *parent)
    : QWidget(parent)
    , m_model(new FieldTreeModel(this))
{
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("frameTitle"));
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_title->hide();

    // How to read the offsets when the bytes shown are not the bytes sent (ASCII frames).
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("frameNote"));
    m_note->setWordWrap(true);
    m_note->setForegroundRole(QPalette::PlaceholderText);
    m_note->hide();

    m_placeholder = new QLabel(this);
    m_placeholder->setObjectName(QStringLiteral("framePlaceholder"));
    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setWordWrap(true);
    m_placeholder->setForegroundRole(QPalette::PlaceholderText);

    m_tree = new FieldTreeView(this);
    m_tree->setObjectName(QStringLiteral("fieldTree"));
    m_tree->setFieldModel(m_model);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_hex = new HexView(this);
    m_hex->setObjectName(QStringLiteral("hexView"));
    m_hex->setBytesPerLine(0);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->addWidget(m_tree);
    m_splitter->addWidget(m_hex);
    m_splitter->setStretchFactor(0, kTreeStretch);
    m_splitter->setStretchFactor(1, kHexStretch);
    m_splitter->setChildrenCollapsible(false);
    connect(m_splitter, &QSplitter::splitterMoved, this, [this] { m_splitterMoved = true; });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_title);
    layout->addWidget(m_note);
    layout->addWidget(m_splitter, 1);
    layout->addWidget(m_placeholder, 1);

    connect(m_tree->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &FrameInspector::onTreeSelection);
    connect(m_hex, &HexView::bytesPicked, this, &FrameInspector::onBytesPicked);
    clear();
}

void FrameInspector::setTitle(const QString &title)
{
    m_title->setText(title);
    m_title->setVisible(!title.isEmpty());
}

QString FrameInspector::title() const
{
    return m_title->text();
}

void FrameInspector::setDissection(const Dissection &dissection)
{
    m_model->setDissection(dissection);
    m_tree->showAllFields();
    m_hex->setBytes(dissection.fields.frame());
    // Problems tint their bytes, outer fields first so an inner field's colour shows on top.
    QList<HexView::Mark> marks;
    const FieldTree &tree = dissection.fields;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        if (f.severity >= Severity::Warning && f.length > 0)
            marks.append({f.offset, f.length, SeverityStyle::backgroundColor(f.severity)});
    }
    m_hex->setMarks(marks);
    m_note->setText(dissection.note);
    m_note->setVisible(!dissection.note.isEmpty());
    m_placeholder->hide();
    m_splitter->show();
    fitSplitter();
}

void FrameInspector::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    fitSplitter();
}

void FrameInspector::fitSplitter()
{
    // The splitter alone would give the hex view its 16-byte width first and squeeze the tree
    // to a sliver in a window under ~1100 px; the tree is what people read.
    const int total = width() - m_splitter->handleWidth();
    if (m_splitterMoved || total <= 0)
        return;
    const int hex = qBound(m_hex->minimumSizeHint().width(), total * kHexSharePercent / 100, m_hex->sizeHint().width());
    m_splitter->setSizes({total - hex, hex});
}

void FrameInspector::clear()
{
    setPlaceholder(tr("No frame"));
}

void FrameInspector::setPlaceholder(const QString &text)
{
    m_model->clear();
    m_hex->clear();
    m_note->hide();
    m_placeholder->setText(text);
    m_splitter->hide();
    m_placeholder->show();
}

const Dissection &FrameInspector::dissection() const
{
    return m_model->dissection();
}

int FrameInspector::selectedField() const
{
    const QModelIndex current = m_tree->currentIndex();
    return current.isValid() ? current.data(FieldTreeModel::FieldIndexRole).toInt() : -1;
}

void FrameInspector::selectField(int field)
{
    const QModelIndex index = field >= 0 ? m_model->indexOfField(field) : QModelIndex();
    if (!index.isValid()) {
        m_tree->selectionModel()->clear();
        m_hex->setSelection(0, 0);
        return;
    }
    m_tree->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_tree->scrollTo(index);
    // Picking another byte of the field already selected changes no row: the field's bytes are
    // highlighted again all the same, so the highlight always shows a whole field.
    const Field &f = m_model->dissection().fields.at(field);
    m_hex->setSelection(f.offset, f.length);
}

void FrameInspector::onTreeSelection()
{
    const int field = selectedField();
    const FieldTree &tree = m_model->dissection().fields;
    if (field >= 0 && field < tree.size())
        m_hex->setSelection(tree.at(field).offset, tree.at(field).length);
    else
        m_hex->setSelection(0, 0);
    Q_EMIT fieldSelected(field);
}

void FrameInspector::onBytesPicked(int offset, int length)
{
    const int field = FieldLocator::innermostField(m_model->dissection().fields, offset, length);
    if (field < 0) {
        m_tree->selectionModel()->clear();
        return;
    }
    selectField(field);
}

} // namespace mbscope
