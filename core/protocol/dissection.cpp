#include "dissection.h"
#include "framingtraits.h"

#include "functioncode.h"
#include "hexformat.h"

namespace mbscope {

QString Dissection::summary() const
{
    const FieldTree &t = fields;
    QString text = QLatin1String(framingTraits(framing).title);
    if (direction != Direction::Auto)
        text += QLatin1Char(' ') + directionName(direction);
    for (const char *key : {"rtu.unit_id", "mbap.unit_id", "ascii.unit_id"}) {
        const int u = t.indexOf(key);
        if (u >= 0) {
            text += QStringLiteral(", unit %1").arg(t.at(u).value);
            break;
        }
    }
    const int f = t.indexOf("modbus.function_code");
    if (f < 0 || t.at(f).length == 0)
        return text + QStringLiteral(": no function code");
    const quint8 code = quint8(t.at(f).value);
    if (code >= 0x80) {
        text += QStringLiteral(": %1 exception").arg(QString::fromLatin1(functionName(code & 0x7F)));
        const int e = t.indexOf("modbus.exception_code");
        if (e >= 0 && t.at(e).length > 0)
            text += QStringLiteral(" %1 %2").arg(hexByte(t.at(e).value),
                                                   QString::fromLatin1(exceptionName(quint8(t.at(e).value))));
    } else {
        text += QStringLiteral(": ") + QString::fromLatin1(functionName(code));
        const int sub = t.indexOf("modbus.subfunction");
        if (sub >= 0 && t.at(sub).meaning)
            text += QStringLiteral(" / ") + QString::fromUtf8(t.at(sub).meaning);
        const int q = t.indexOf("modbus.quantity");
        const int a = t.indexOf("modbus.start_address");
        const int regs = int(t.indexesOf("modbus.register_value").size());
        const int coils = int(t.indexesOf("modbus.coil_value").size() + t.indexesOf("modbus.discrete_input_value").size());
        if (q >= 0 && a >= 0)
            text += QStringLiteral(", %1 from address %2").arg(t.at(q).value).arg(t.valueText(a));
        else if (a >= 0)
            text += QStringLiteral(", address %1").arg(t.valueText(a));
        const int single = t.indexOf("modbus.address");
        const int value = t.indexOf("modbus.value");
        if (single >= 0 && value >= 0)
            text += QStringLiteral(", address %1 = %2").arg(t.valueText(single), t.display(value));
        if (regs > 0 && q < 0)
            text += QStringLiteral(", %1 register value%2").arg(regs).arg(regs == 1 ? QString() : QStringLiteral("s"));
        if (coils > 0 && q < 0)
            text += QStringLiteral(", %1 bit%2").arg(coils).arg(coils == 1 ? QString() : QStringLiteral("s"));
    }
    const int errors = t.count(Severity::Error);
    const int warnings = t.count(Severity::Warning);
    if (errors > 0)
        text += QStringLiteral(" [%1 error%2]").arg(errors).arg(errors == 1 ? QString() : QStringLiteral("s"));
    if (warnings > 0)
        text += QStringLiteral(" [%1 warning%2]").arg(warnings).arg(warnings == 1 ? QString() : QStringLiteral("s"));
    return text;
}

} // namespace mbscope
