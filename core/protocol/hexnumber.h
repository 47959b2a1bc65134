#pragma once

#include <QtCore/QString>

namespace mbscope {

// A number as upper-case hex digits, at least `digits` of them, without a prefix:
// hexNumber(0x1AF, 4) == "01AF". The convention of every output (CLI, reports, messages): the
// digits in upper case, a "0x" before them in lower case ("0x01AF"), as HexText::format writes bytes.
[[nodiscard]] inline QString hexNumber(quint64 value, int digits)
{
    return QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'));
}

} // namespace mbscope
