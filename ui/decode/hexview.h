#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtGui/QColor>
#include <QtWidgets/QAbstractScrollArea>

namespace mbscope {

// A hex dump of one frame: offset column, hex bytes, printable ASCII, painted by itself (no item
// per byte) so a long garbage run scrolls as fast as an 8-byte request. It knows nothing of
// fields: it shows one selected byte range, strong, and any number of marked ranges as tints
// (problems, by severity); a click or a drag reports the bytes the user picked, and the owner
// decides what they mean (FrameInspector selects the field that covers them).
class HexView : public QAbstractScrollArea
{
    Q_OBJECT

public:
    // A tinted byte range: a field with a problem.
    struct Mark {
        int offset = 0;
        int length = 0;
        QColor background;
    };

    // Where a byte is drawn: the hex column or the ASCII column.
    enum class Area : quint8 { Hex, Ascii };

    explicit HexView(QWidget *parent = nullptr);

    void setBytes(const QByteArray &bytes); // clears the selection and the marks
    [[nodiscard]] const QByteArray &bytes() const { return m_bytes; }
    void clear();

    // 4, 8 or 16 (the default): a short frame reads best on one or two lines. 0: as many of
    // 16, 8 or 4 as fit the width with the ASCII column (the decode view's panes, which must
    // leave room to the field tree in a narrow window).
    void setBytesPerLine(int count);
    [[nodiscard]] int bytesPerLine() const { return m_bytesPerLine; }
    [[nodiscard]] bool fitsBytesPerLine() const { return m_fitBytesPerLine; }

    // Highlights [offset, offset + length) and scrolls it into view; length 0 clears. Does not
    // emit bytesPicked: that is for what the user does.
    void setSelection(int offset, int length);
    [[nodiscard]] int selectionOffset() const { return m_selOffset; }
    [[nodiscard]] int selectionLength() const { return m_selLength; }

    void setMarks(const QList<Mark> &marks);
    [[nodiscard]] const QList<Mark> &marks() const { return m_marks; }

    // The byte under a point of the viewport (hex or ASCII column), or -1.
    [[nodiscard]] int byteAt(const QPoint &viewportPos) const;
    // Where a byte is drawn in viewport coordinates (for tests and tooltips); null when scrolled out.
    [[nodiscard]] QRect byteRect(int offset, Area area = Area::Hex) const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

Q_SIGNALS:
    // The user clicked a byte, dragged over a range or moved with the keyboard: the bytes picked,
    // already shown as the selection.
    void bytesPicked(int offset, int length);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;
    bool viewportEvent(QEvent *event) override;

private:
    void updateMetrics();
    void updateScrollBars();
    void pick(int anchor, int current);
    void ensureVisible(int offset);
    [[nodiscard]] int lineCount() const;
    // Width of the offset, hex and ASCII columns with perLine bytes a line, in pixels.
    [[nodiscard]] int contentWidth(int perLine) const;
    void fitBytesPerLine();
    [[nodiscard]] int hexX(int column) const;
    [[nodiscard]] int asciiX(int column) const;
    [[nodiscard]] QColor markAt(int offset) const;

    QByteArray m_bytes;
    QList<Mark> m_marks;
    int m_bytesPerLine = 16;
    bool m_fitBytesPerLine = false;
    int m_selOffset = 0;
    int m_selLength = 0;
    int m_anchor = -1; // the byte a drag started on
    int m_charWidth = 8;
    int m_lineHeight = 16;
    int m_ascent = 12;
    int m_offsetDigits = 4;
};

} // namespace mbscope
