#include "common/requestnames.h"

#include "protocol/functioncode.h"
#include "protocol/modiconreference.h"

namespace mbscope::app {

namespace {

// The Modicon references of a run of items: "40122-40143", or "40122" for one.
QString referenceRange(quint8 functionCode, int address, int quantity)
{
    const auto table = ModiconReference::tableOf(functionCode);
    if (!table || address < 0 || quantity < 1 || address + quantity - 1 > 0xFFFF)
        return {};
    const ModiconReference first(*table, quint16(address));
    const ModiconReference last(*table, quint16(address + quantity - 1));
    const bool five = last.hasFiveDigitForm();
    const QString a = five ? first.fiveDigit() : first.sixDigit();
    const QString b = five ? last.fiveDigit() : last.sixDigit();
    return quantity == 1 ? a : a + QLatin1Char('-') + b;
}

} // namespace

QString RequestNames::hex4(int address)
{
    return QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}

QString RequestNames::describeItems(quint8 functionCode, int unit, int address, int quantity, const char *items,
                                    bool oneBased)
{
    const QString where = oneBased ? QStringLiteral("%1 (1-based; PDU address %2, 0x%3)").arg(address + 1).arg(address).arg(hex4(address))
                                   : QStringLiteral("%1 (0x%2)").arg(address).arg(hex4(address));
    QString text = QStringLiteral("unit %1, %2 %3 at %4")
                       .arg(unit)
                       .arg(quantity)
                       .arg(QLatin1String(items), where);
    const QString refs = referenceRange(functionCode, address, quantity);
    if (!refs.isEmpty())
        text += QStringLiteral(", ") + refs;
    return text;
}

QString RequestNames::describe(quint8 functionCode, int unit, int address, int quantity, const char *items, bool oneBased)
{
    return QString::fromLatin1(functionName(functionCode)) + QStringLiteral(", ")
           + describeItems(functionCode, unit, address, quantity, items, oneBased);
}

const char *RequestNames::readNoun(quint8 functionCode, int quantity)
{
    if (functionCode >= 3)
        return quantity == 1 ? "register" : "registers";
    if (functionCode == 1)
        return quantity == 1 ? "coil" : "coils";
    return quantity == 1 ? "discrete input" : "discrete inputs";
}

QString RequestNames::itemName(quint8 functionCode, int address, int quantity, bool oneBased)
{
    return oneBased ? QStringLiteral("%1 %2 x%3 (1-based)").arg(QString::fromLatin1(functionName(functionCode))).arg(address + 1).arg(quantity)
                    : QStringLiteral("%1 %2 x%3").arg(QString::fromLatin1(functionName(functionCode))).arg(address).arg(quantity);
}

} // namespace mbscope::app
