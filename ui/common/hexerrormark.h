#pragma once

#include "protocol/hextext.h"

class QLabel;
class QPlainTextEdit;
class QString;
class QWidget;

namespace mbscope {

// How the editors show what is wrong with typed hex, one look everywhere.
namespace hexerrormark {

// Underlines the character the parser stopped at (HexTextError's line and column, from 1), so
// the user sees it without counting columns; an empty message clears the mark.
void mark(QPlainTextEdit *edit, const HexTextError &error);

// A hidden, word-wrapped, selectable label in the error colour, for messages shown in place.
[[nodiscard]] QLabel *newErrorLabel(const QString &objectName, QWidget *parent);

} // namespace hexerrormark
} // namespace mbscope
