#include "registerwrite.h"

#include "profile/scaledvalue.h"
#include "protocol/registervalue.h"

#include <QtCore/QLocale>

namespace mbscope {

namespace {

TableWriteResult refused(const QString &error)
{
    TableWriteResult result;
    result.error = error;
    return result;
}

} // namespace

TableWriteResult RegisterWrite::coil(const ReadAnswerRows &rows, int row, const QString &text, WriteChoice choice)
{
    const std::optional<bool> on = TableWrite::coilFromText(text);
    if (!on)
        return refused(tr("%1: '%2' is not a coil value: expected 1 or 0 (on/off, true/false)")
                           .arg(where(rows, row), text.trimmed()));
    return TableWrite::coil(rows.address(row), *on, choice);
}

TableWriteResult RegisterWrite::value(const ReadAnswerRows &rows, int row, RegisterFormat format, const QString &text,
                                      WriteChoice choice)
{
    // Spaces are characters in ASCII ("A " is 0x4120); elsewhere they only surround the number.
    const RegisterValueResult v =
        RegisterValue::fromText(format.type() == RegisterType::Ascii ? text : text.trimmed(), format);
    if (!v.ok)
        return refused(tr("%1, %2").arg(where(rows, row), format.name() + QLatin1String(": ") + v.error));
    return TableWrite::registers(rows.address(row), v.value.registers(), choice);
}

TableWriteResult RegisterWrite::scaled(const ReadAnswerRows &rows, int row, const QString &text, WriteChoice choice)
{
    const TableEntry *entry = rows.entryAt(row).entry;
    if (!entry)
        return refused(where(rows, row));
    const QString trimmed = text.trimmed();
    QString number = trimmed;
    if (!entry->unit.isEmpty() && number.endsWith(entry->unit))
        number = number.chopped(entry->unit.size()).trimmed();
    QString error;
    RegisterValueResult v;
    if (entry->scale == 1 && entry->offset == 0) {
        v = RegisterValue::fromText(number, entry->format);
        if (!v.ok)
            error = entry->format.name() + QLatin1String(": ") + v.error;
    } else {
        bool ok = false;
        const double engineering = QLocale::c().toDouble(number, &ok);
        if (!ok) {
            error = tr("'%1' is not a number: the scaled value of %2 takes a decimal number").arg(trimmed, entry->name);
        } else {
            v = ScaledValue{entry->format, entry->scale, entry->offset}.encode(engineering);
            if (!v.ok)
                error = tr("%1 %2 (raw = (value - %3) / %4): %5")
                            .arg(entry->name, entry->format.name())
                            .arg(entry->offset)
                            .arg(entry->scale)
                            .arg(v.error);
        }
    }
    if (!error.isEmpty())
        return refused(tr("%1, %2").arg(where(rows, row), error));
    return TableWrite::registers(rows.address(row), v.value.registers(), choice);
}

QString RegisterWrite::where(const ReadAnswerRows &rows, int row)
{
    const int address = rows.address(row);
    const QString reference = ReadAnswer::referenceText(rows.reference(row));
    if (!rows.isBits())
        return tr("register %1 (PDU address %2)").arg(reference).arg(address);
    return rows.answer().table == ModbusTable::Coils
        ? tr("coil %1 (PDU address %2)").arg(reference).arg(address)
        : tr("discrete input %1 (PDU address %2)").arg(reference).arg(address);
}

} // namespace mbscope
