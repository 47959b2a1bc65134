#include "hexview.h"

#include <QtGui/QFontDatabase>
#include <QtGui/QKeyEvent>
#include <QtGui/QMouseEvent>
#include <QtGui/QPainter>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QToolTip>

namespace mbscope {

namespace {

// Bytes in a group: a gap after the eighth byte of a 16-byte line, as in hexdump -C and Wireshark.
constexpr int kGroup = 8;
// Lines a hint asks room for: a 44-byte answer (three lines) with room to spare.
constexpr int kHintLines = 6;

bool isPrintable(char c)
{
    return c >= 0x20 && c < 0x7F;
}

} // namespace

HexView::HexView(QWidget *parent)
    : QAbstractScrollArea(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setCursor(Qt::IBeamCursor);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
    updateMetrics();
}

void HexView::setBytes(const QByteArray &bytes)
{
    m_bytes = bytes;
    m_marks.clear();
    m_selOffset = 0;
    m_selLength = 0;
    m_anchor = -1;
    updateMetrics();
    verticalScrollBar()->setValue(0);
    viewport()->update();
}

void HexView::clear()
{
    setBytes({});
}

void HexView::setBytesPerLine(int count)
{
    m_fitBytesPerLine = count <= 0;
    if (m_fitBytesPerLine)
        fitBytesPerLine();
    else
        m_bytesPerLine = count <= 4 ? 4 : count <= 8 ? 8 : 16;
    updateMetrics();
    updateGeometry();
    viewport()->update();
}

void HexView::setSelection(int offset, int length)
{
    const int size = int(m_bytes.size());
    offset = qBound(0, offset, size);
    length = qBound(0, length, size - offset);
    if (offset == m_selOffset && length == m_selLength)
        return;
    m_selOffset = offset;
    m_selLength = length;
    if (length > 0)
        ensureVisible(offset);
    viewport()->update();
}

void HexView::setMarks(const QList<Mark> &marks)
{
    m_marks = marks;
    viewport()->update();
}

int HexView::lineCount() const
{
    return int((m_bytes.size() + m_bytesPerLine - 1) / m_bytesPerLine);
}

int HexView::hexX(int column) const
{
    const int margin = m_charWidth / 2;
    return margin + (m_offsetDigits + 2) * m_charWidth + column * 3 * m_charWidth
        + (column >= kGroup ? m_charWidth : 0);
}

int HexView::asciiX(int column) const
{
    return hexX(m_bytesPerLine) + m_charWidth + column * m_charWidth;
}

int HexView::contentWidth(int perLine) const
{
    // As hexX and asciiX lay a line out, for another count of bytes.
    const int margin = m_charWidth / 2;
    return margin + (m_offsetDigits + 2) * m_charWidth + perLine * 3 * m_charWidth + (perLine >= kGroup ? m_charWidth : 0)
        + m_charWidth + perLine * m_charWidth + margin;
}

void HexView::fitBytesPerLine()
{
    // Against the width with a vertical scroll bar, shown or not, so that the bar coming and going
    // with the line count cannot flip the choice back and forth.
    const int room = width() - 2 * frameWidth() - verticalScrollBar()->sizeHint().width();
    int perLine = 4;
    for (const int candidate : {16, 8}) {
        if (contentWidth(candidate) <= room) {
            perLine = candidate;
            break;
        }
    }
    if (perLine == m_bytesPerLine)
        return;
    m_bytesPerLine = perLine;
    updateScrollBars();
    if (m_selLength > 0)
        ensureVisible(m_selOffset);
    viewport()->update();
}

void HexView::updateMetrics()
{
    const QFontMetrics fm(font());
    m_charWidth = qMax(1, fm.horizontalAdvance(QLatin1Char('0')));
    m_lineHeight = fm.height() + 2;
    m_ascent = fm.ascent() + 1;
    m_offsetDigits = m_bytes.size() > 0xFFFF ? 8 : 4;
    if (m_fitBytesPerLine)
        fitBytesPerLine();
    updateScrollBars();
}

void HexView::updateScrollBars()
{
    const int visibleLines = qMax(1, viewport()->height() / m_lineHeight);
    verticalScrollBar()->setRange(0, qMax(0, lineCount() - visibleLines));
    verticalScrollBar()->setPageStep(visibleLines);
    verticalScrollBar()->setSingleStep(1);
    const int width = asciiX(m_bytesPerLine) + m_charWidth / 2;
    horizontalScrollBar()->setRange(0, qMax(0, width - viewport()->width()));
    horizontalScrollBar()->setPageStep(viewport()->width());
    horizontalScrollBar()->setSingleStep(m_charWidth);
}

void HexView::ensureVisible(int offset)
{
    const int line = offset / m_bytesPerLine;
    const int visibleLines = qMax(1, viewport()->height() / m_lineHeight);
    QScrollBar *bar = verticalScrollBar();
    if (line < bar->value())
        bar->setValue(line);
    else if (line >= bar->value() + visibleLines)
        bar->setValue(line - visibleLines + 1);
}

QColor HexView::markAt(int offset) const
{
    // The last mark wins: callers list outer fields before inner ones.
    QColor color;
    for (const Mark &m : m_marks) {
        if (offset >= m.offset && offset < m.offset + m.length)
            color = m.background;
    }
    return color;
}

int HexView::byteAt(const QPoint &viewportPos) const
{
    const int x = viewportPos.x() + horizontalScrollBar()->value();
    const int line = verticalScrollBar()->value() + viewportPos.y() / m_lineHeight;
    if (viewportPos.y() < 0 || line >= lineCount())
        return -1;
    int column = -1;
    if (x >= hexX(0) - m_charWidth / 2 && x < hexX(m_bytesPerLine)) {
        for (int c = m_bytesPerLine - 1; c >= 0; --c) {
            if (x >= hexX(c) - m_charWidth / 2) {
                column = c;
                break;
            }
        }
    } else if (x >= asciiX(0) && x < asciiX(m_bytesPerLine)) {
        column = (x - asciiX(0)) / m_charWidth;
    }
    if (column < 0)
        return -1;
    const int offset = line * m_bytesPerLine + column;
    return offset < m_bytes.size() ? offset : -1;
}

QRect HexView::byteRect(int offset, Area area) const
{
    if (offset < 0 || offset >= m_bytes.size())
        return {};
    const int line = offset / m_bytesPerLine - verticalScrollBar()->value();
    if (line < 0 || line * m_lineHeight > viewport()->height())
        return {};
    const int column = offset % m_bytesPerLine;
    const int x = (area == Area::Hex ? hexX(column) : asciiX(column)) - horizontalScrollBar()->value();
    const int w = area == Area::Hex ? 2 * m_charWidth : m_charWidth;
    return {x, line * m_lineHeight, w, m_lineHeight};
}

QSize HexView::sizeHint() const
{
    const int frame = 2 * frameWidth();
    const int lines = qBound(2, lineCount(), kHintLines);
    if (m_fitBytesPerLine) // the widest it would use
        return {contentWidth(16) + frame + verticalScrollBar()->sizeHint().width(), lines * m_lineHeight + frame};
    return {asciiX(m_bytesPerLine) + m_charWidth / 2 + frame + verticalScrollBar()->sizeHint().width(),
            lines * m_lineHeight + frame};
}

QSize HexView::minimumSizeHint() const
{
    // Fitting: four bytes a line with their characters, nothing cut off.
    if (m_fitBytesPerLine)
        return {contentWidth(4) + 2 * frameWidth() + verticalScrollBar()->sizeHint().width(), 2 * m_lineHeight + 2 * frameWidth()};
    return {hexX(kGroup) + 2 * frameWidth(), 2 * m_lineHeight + 2 * frameWidth()};
}

void HexView::paintEvent(QPaintEvent *)
{
    QPainter painter(viewport());
    painter.setFont(font());
    const QPalette &pal = palette();
    const QColor textColor = pal.color(QPalette::Text);
    const QColor offsetColor = pal.color(QPalette::PlaceholderText);
    const QColor selectionColor = pal.color(QPalette::Highlight);
    const QColor selectedText = pal.color(QPalette::HighlightedText);
    const int dx = -horizontalScrollBar()->value();
    const int firstLine = verticalScrollBar()->value();
    const int lastLine = qMin(lineCount(), firstLine + viewport()->height() / m_lineHeight + 2);
    const int selEnd = m_selOffset + m_selLength;
    const char *raw = m_bytes.constData();
    // A byte's tint reaches over the gap to the next byte when that one is tinted the same, so a
    // field's bytes read as one block and neighbouring fields stay apart.
    constexpr int kPad = 2;

    for (int line = firstLine; line < lastLine; ++line) {
        const int y = (line - firstLine) * m_lineHeight;
        const int base = line * m_bytesPerLine;
        painter.setPen(offsetColor);
        painter.drawText(m_charWidth / 2 + dx, y + m_ascent,
                         QString::number(base, 16).toUpper().rightJustified(m_offsetDigits, QLatin1Char('0')));
        const int count = qMin(m_bytesPerLine, int(m_bytes.size()) - base);
        for (int c = 0; c < count; ++c) {
            const int offset = base + c;
            const bool selected = offset >= m_selOffset && offset < selEnd;
            QColor background = selected ? selectionColor : markAt(offset);
            if (background.isValid()) {
                const bool joins = c + 1 < count && c + 1 != kGroup
                    && ((offset + 1 >= m_selOffset && offset + 1 < selEnd) == selected)
                    && (selected || markAt(offset + 1) == background);
                const int left = hexX(c) - kPad + dx;
                const int right = joins ? hexX(c + 1) - kPad + dx : hexX(c) + 2 * m_charWidth + kPad + dx;
                painter.fillRect(QRect(left, y, right - left, m_lineHeight), background);
                painter.fillRect(QRect(asciiX(c) + dx, y, m_charWidth, m_lineHeight), background);
            }
            const auto byte = quint8(raw[offset]);
            static constexpr char kDigits[] = "0123456789ABCDEF";
            const QChar hexChars[2] = {QLatin1Char(kDigits[byte >> 4]), QLatin1Char(kDigits[byte & 0xF])};
            painter.setPen(selected ? selectedText : textColor);
            painter.drawText(hexX(c) + dx, y + m_ascent, QString(hexChars, 2));
            const char ch = raw[offset];
            if (!isPrintable(ch))
                painter.setPen(selected ? selectedText : offsetColor);
            painter.drawText(asciiX(c) + dx, y + m_ascent, QString(QLatin1Char(isPrintable(ch) ? ch : '.')));
        }
    }
    // A thin rule between the hex and the ASCII columns.
    painter.setPen(pal.color(QPalette::Mid));
    const int ruleX = hexX(m_bytesPerLine) + dx;
    painter.drawLine(ruleX, 0, ruleX, (lastLine - firstLine) * m_lineHeight);
}

void HexView::resizeEvent(QResizeEvent *event)
{
    QAbstractScrollArea::resizeEvent(event);
    if (m_fitBytesPerLine)
        fitBytesPerLine();
    updateScrollBars();
}

void HexView::pick(int anchor, int current)
{
    const int first = qMin(anchor, current);
    const int last = qMax(anchor, current);
    m_selOffset = -1; // so setSelection repaints even when the span is unchanged
    setSelection(first, last - first + 1);
    Q_EMIT bytesPicked(first, last - first + 1);
}

void HexView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QAbstractScrollArea::mousePressEvent(event);
    const int offset = byteAt(event->position().toPoint());
    m_anchor = offset;
    if (offset >= 0)
        pick(offset, offset);
}

void HexView::mouseMoveEvent(QMouseEvent *event)
{
    if (!(event->buttons() & Qt::LeftButton) || m_anchor < 0)
        return QAbstractScrollArea::mouseMoveEvent(event);
    const int offset = byteAt(event->position().toPoint());
    if (offset >= 0)
        pick(m_anchor, offset);
}

void HexView::mouseReleaseEvent(QMouseEvent *event)
{
    m_anchor = -1;
    QAbstractScrollArea::mouseReleaseEvent(event);
}

void HexView::keyPressEvent(QKeyEvent *event)
{
    if (m_bytes.isEmpty())
        return QAbstractScrollArea::keyPressEvent(event);
    const int last = int(m_bytes.size()) - 1;
    const bool none = m_selLength == 0;
    int target = -1;
    switch (event->key()) {
    case Qt::Key_Right:
        target = none ? 0 : qMin(last, m_selOffset + m_selLength);
        break;
    case Qt::Key_Left:
        target = none ? 0 : qMax(0, m_selOffset - 1);
        break;
    case Qt::Key_Down:
        target = none ? 0 : qMin(last, m_selOffset + m_bytesPerLine);
        break;
    case Qt::Key_Up:
        target = none ? 0 : qMax(0, m_selOffset - m_bytesPerLine);
        break;
    case Qt::Key_Home:
        target = 0;
        break;
    case Qt::Key_End:
        target = last;
        break;
    default:
        return QAbstractScrollArea::keyPressEvent(event);
    }
    pick(target, target);
}

void HexView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange)
        updateMetrics();
    QAbstractScrollArea::changeEvent(event);
}

bool HexView::viewportEvent(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto *help = static_cast<QHelpEvent *>(event);
        const int offset = byteAt(help->pos());
        if (offset < 0) {
            QToolTip::hideText();
            return true;
        }
        const auto byte = quint8(m_bytes.at(offset));
        QToolTip::showText(help->globalPos(),
                           tr("Offset %1 (0x%2): 0x%3 = %4")
                               .arg(offset)
                               .arg(QString::number(offset, 16).toUpper().rightJustified(4, QLatin1Char('0')))
                               .arg(QString::number(byte, 16).toUpper().rightJustified(2, QLatin1Char('0')))
                               .arg(byte),
                           viewport());
        return true;
    }
    return QAbstractScrollArea::viewportEvent(event);
}

} // namespace mbscope
