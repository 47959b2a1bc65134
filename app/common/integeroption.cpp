#include "common/integeroption.h"

namespace mbscope::app {

IntegerResult parseInteger(const QString &option, const QString &text)
{
    IntegerResult result;
    const QString t = text.trimmed();
    bool ok = false;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        result.value = t.mid(2).toLongLong(&ok, 16);
    else if (!t.startsWith(QLatin1Char('+')))
        result.value = t.toLongLong(&ok, 10);
    if (!ok) {
        result.error = QStringLiteral("%1 '%2' is not a number: expected decimal or 0x hex (e.g. 121 or 0x79)")
                           .arg(option, text);
        return result;
    }
    result.ok = true;
    return result;
}

IntegerResult parseInteger(const QString &option, const QString &text, qint64 low, qint64 high, const QString &what)
{
    IntegerResult result = parseInteger(option, text);
    if (result.ok && (result.value < low || result.value > high)) {
        result.ok = false;
        result.error = QStringLiteral("%1 %2 is out of range: expected %3 to %4%5")
                           .arg(option, text.trimmed())
                           .arg(low)
                           .arg(high)
                           .arg(what.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(what));
    }
    return result;
}

} // namespace mbscope::app
