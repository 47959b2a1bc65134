#include "watchvaluewrite.h"

#include "profile/scaledvalue.h"
#include "protocol/registervalue.h"
#include "protocol/tablewrite.h"
#include "watch/watchdecoder.h"
#include "watch/watchblock.h"

#include <QtCore/QLocale>

namespace mbscope {

bool WatchValueWrite::isWritable(const WatchDefinition &watch, int point)
{
    return point >= 0 && point < watch.points.size() && watch.points.at(point).writable
        && (watch.function == 1 || watch.function == 3);
}

WatchWriteWords WatchValueWrite::words(const WatchDefinition &watch, int index, const QString &text)
{
    WatchWriteWords result;
    if (!isWritable(watch, index)) {
        result.error = tr("%1: only points marked writable of a coil (01) or holding register (03) watch are written")
                           .arg(watch.name);
        return result;
    }
    const WatchPoint &point = watch.points.at(index);
    const QString where = point.name.isEmpty() ? tr("address %1").arg(point.address)
                                               : tr("%1 (address %2)").arg(point.name).arg(point.address);
    if (watch.function == 1) {
        const std::optional<bool> on = TableWrite::coilFromText(text);
        if (!on)
            result.error = tr("%1: '%2' is not a coil value: expected 1 or 0 (on/off, true/false)").arg(where, text.trimmed());
        else
            result.words = {quint16(*on ? 1 : 0)};
        return result;
    }
    const RegisterFormat format = WatchBlock::effectiveFormat(watch, point);
    QString number = text.trimmed();
    if (!point.unit.isEmpty() && number.endsWith(point.unit))
        number = number.chopped(point.unit.size()).trimmed();
    RegisterValueResult value;
    if (point.scale == 1 && point.offset == 0) {
        value = RegisterValue::fromText(format.type() == RegisterType::Ascii ? text : number, format);
        if (!value.ok)
            result.error = QStringLiteral("%1, %2: %3").arg(where, format.name(), value.error);
    } else {
        bool ok = false;
        const double engineering = QLocale::c().toDouble(number, &ok);
        if (!ok) {
            result.error = tr("%1: '%2' is not a number (the point is scaled: raw = (value - %3) / %4)")
                               .arg(where, text.trimmed())
                               .arg(point.offset)
                               .arg(point.scale);
            return result;
        }
        value = ScaledValue{format, point.scale, point.offset}.encode(engineering);
        if (!value.ok)
            result.error = QStringLiteral("%1, %2: %3").arg(where, format.name(), value.error);
    }
    if (value.ok)
        result.words = value.value.registers();
    return result;
}

} // namespace mbscope
