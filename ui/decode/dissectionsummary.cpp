#include "dissectionsummary.h"

#include "common/coretext.h"

#include "protocol/framingtraits.h"
#include "protocol/functioncode.h"
#include "protocol/hexformat.h"

namespace mbscope {

namespace {

QString framingTitle(Framing framing)
{
    // The framing's own names are the standard's, left in English (framingtraits.h).
    if (framing == Framing::Auto)
        return DissectionSummary::tr("Frame");
    return QLatin1String(framingTraits(framing).title);
}

} // namespace

QString DissectionSummary::text(const Dissection &dissection)
{
    const FieldTree &t = dissection.fields;
    QString text = framingTitle(dissection.framing);
    if (dissection.direction == Direction::Request)
        text = tr("%1 request").arg(text);
    else if (dissection.direction == Direction::Response)
        text = tr("%1 response").arg(text);
    for (const char *key : {"rtu.unit_id", "mbap.unit_id", "ascii.unit_id"}) {
        const int u = t.indexOf(key);
        if (u >= 0) {
            text = tr("%1, unit %2").arg(text).arg(t.at(u).value);
            break;
        }
    }
    const int f = t.indexOf("modbus.function_code");
    if (f < 0 || t.at(f).length == 0)
        return tr("%1: no function code").arg(text);
    const quint8 code = quint8(t.at(f).value);
    if (code >= 0x80) {
        text = tr("%1: %2 exception").arg(text, fieldText(functionName(code & 0x7F)));
        const int e = t.indexOf("modbus.exception_code");
        if (e >= 0 && t.at(e).length > 0)
            text += QStringLiteral(" %1 %2").arg(hexByte(t.at(e).value), fieldText(exceptionName(quint8(t.at(e).value))));
    } else {
        text = tr("%1: %2").arg(text, fieldText(functionName(code)));
        const int sub = t.indexOf("modbus.subfunction");
        if (sub >= 0 && t.at(sub).meaning)
            text += QStringLiteral(" / ") + fieldText(t.at(sub).meaning);
        const int q = t.indexOf("modbus.quantity");
        const int a = t.indexOf("modbus.start_address");
        const int regs = int(t.indexesOf("modbus.register_value").size());
        const int coils = int(t.indexesOf("modbus.coil_value").size() + t.indexesOf("modbus.discrete_input_value").size());
        if (q >= 0 && a >= 0)
            text = tr("%1, %2 from address %3").arg(text).arg(t.at(q).value).arg(t.valueText(a));
        else if (a >= 0)
            text = tr("%1, address %2").arg(text, t.valueText(a));
        const int single = t.indexOf("modbus.address");
        const int value = t.indexOf("modbus.value");
        if (single >= 0 && value >= 0) {
            const Field &v = t.at(value);
            // FieldTree::display, translated: the value, then its meaning.
            QString shown = t.valueText(value);
            if (v.meaning && *v.meaning)
                shown += (shown.isEmpty() ? QString() : QStringLiteral(" ")) + fieldText(v.meaning);
            text = tr("%1, address %2 = %3").arg(text, t.valueText(single), shown);
        }
        if (regs > 0 && q < 0)
            text = regs == 1 ? tr("%1, 1 register value").arg(text) : tr("%1, %2 register values").arg(text).arg(regs);
        if (coils > 0 && q < 0)
            text = coils == 1 ? tr("%1, 1 bit").arg(text) : tr("%1, %2 bits").arg(text).arg(coils);
    }
    const int errors = t.count(Severity::Error);
    const int warnings = t.count(Severity::Warning);
    if (errors > 0)
        text += QLatin1Char(' ') + (errors == 1 ? tr("[1 error]") : tr("[%1 errors]").arg(errors));
    if (warnings > 0)
        text += QLatin1Char(' ') + (warnings == 1 ? tr("[1 warning]") : tr("[%1 warnings]").arg(warnings));
    return text;
}

} // namespace mbscope
