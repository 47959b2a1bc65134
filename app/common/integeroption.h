#pragma once

#include <QtCore/QString>

namespace mbscope::app {

// A whole number option: decimal, or hex with 0x ("0x79"). nullopt-like: ok false with the
// message "--address '12x' is not a number: expected decimal or 0x hex (e.g. 121 or 0x79)".
struct IntegerResult {
    qint64 value = 0;
    QString error;
    bool ok = false;
};
[[nodiscard]] IntegerResult parseInteger(const QString &option, const QString &text);
// The same, within [low, high], the message naming the range.
[[nodiscard]] IntegerResult parseInteger(const QString &option, const QString &text, qint64 low, qint64 high,
                                         const QString &what = {});

} // namespace mbscope::app
