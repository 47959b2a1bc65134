#pragma once

#include "protocol/dissection.h"

#include <QtWidgets/QWidget>

class QLabel;
class QSplitter;

namespace mbscope {

class FieldTreeModel;
class FieldTreeView;
class HexView;

// One frame as Wireshark shows a packet: its field tree beside its bytes. Selecting a field
// highlights its bytes; clicking or dragging over bytes selects the innermost field covering them.
// Fields with problems tint their bytes with their severity's colour. The bytes shown are the
// dissection's (an ASCII frame's decoded bytes, with the dissection's note on how to read them).
class FrameInspector : public QWidget
{
    Q_OBJECT

public:
    explicit FrameInspector(QWidget *parent = nullptr);

    // A bold line above the pair ("Request", "Response · 12.3 ms"); empty hides it.
    void setTitle(const QString &title);
    [[nodiscard]] QString title() const;

    void setDissection(const Dissection &dissection);
    void clear();
    // Shown instead of the frame when there is none ("No answer: timeout").
    void setPlaceholder(const QString &text);
    [[nodiscard]] const Dissection &dissection() const;

    // The field selected in the tree (index in the FieldTree), or -1.
    [[nodiscard]] int selectedField() const;
    // Selects a field in the tree (and so its bytes); -1 clears.
    void selectField(int field);

    [[nodiscard]] FieldTreeModel *model() const { return m_model; }
    [[nodiscard]] FieldTreeView *treeView() const { return m_tree; }
    [[nodiscard]] HexView *hexView() const { return m_hex; }

Q_SIGNALS:
    void fieldSelected(int field);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    // Shares the width between tree and bytes until the user moves the handle.
    void fitSplitter();
    void onTreeSelection();
    void onBytesPicked(int offset, int length);

    QLabel *m_title = nullptr;
    QLabel *m_note = nullptr;
    QLabel *m_placeholder = nullptr;
    QSplitter *m_splitter = nullptr;
    FieldTreeModel *m_model = nullptr;
    FieldTreeView *m_tree = nullptr;
    HexView *m_hex = nullptr;
    bool m_splitterMoved = false; // by the user: the split is theirs from then on
};

} // namespace mbscope
