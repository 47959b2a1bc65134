#include "hexerrormark.h"

#include "severitystyle.h"

#include <QtGui/QTextBlock>
#include <QtGui/QTextCursor>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>

namespace mbscope::hexerrormark {

void mark(QPlainTextEdit *edit, const HexTextError &error)
{
    if (error.message.isEmpty()) {
        edit->setExtraSelections({});
        return;
    }
    const QTextBlock block = edit->document()->findBlockByNumber(error.line - 1);
    if (!block.isValid())
        return;
    QTextCursor cursor(block);
    const int column = qBound(0, error.column - 1, qMax(0, block.length() - 1));
    cursor.setPosition(block.position() + column);
    // At the end of the line (a missing digit) the mark falls on the character before.
    if (column < block.length() - 1)
        cursor.movePosition(QTextCursor::NextCharacter, QTextCursor::KeepAnchor);
    else
        cursor.movePosition(QTextCursor::PreviousCharacter, QTextCursor::KeepAnchor);
    QTextEdit::ExtraSelection selection;
    selection.cursor = cursor;
    selection.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
    selection.format.setUnderlineColor(SeverityStyle::hue(Severity::Error));
    selection.format.setBackground(SeverityStyle::backgroundColor(Severity::Error));
    edit->setExtraSelections({selection});
}

QLabel *newErrorLabel(const QString &objectName, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QPalette palette = label->palette();
    palette.setColor(QPalette::WindowText, SeverityStyle::textColor(Severity::Error));
    label->setPalette(palette);
    label->hide();
    return label;
}

} // namespace mbscope::hexerrormark
