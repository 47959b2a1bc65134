#include "tablewrite.h"

#include "functioncode.h"
#include "hexformat.h"
#include "readanswer.h"
#include "requestbuilder.h"

namespace mbscope {

namespace {

TableWriteResult finish(const BuildResult &built, quint8 code, QString what)
{
    TableWriteResult result;
    result.functionCode = code;
    if (!built.isValid()) {
        result.error = built.errorString();
        return result;
    }
    result.pdu = built.pdu;
    result.description = hexDigits(code, 2) + QLatin1Char(' ') + QLatin1String(functionName(code))
        + QLatin1String(": ") + what;
    result.ok = true;
    return result;
}

QString where(ModbusTable table, int address)
{
    if (address < 0 || address > 0xFFFF)
        return QStringLiteral("PDU address %1").arg(address);
    return ReadAnswer::referenceText(ModiconReference(table, quint16(address)))
        + QStringLiteral(" (PDU address %1)").arg(address);
}

} // namespace

quint8 TableWrite::functionFor(ModbusTable table, int registerCount, WriteChoice choice)
{
    switch (table) {
    case ModbusTable::Coils:
        return choice == WriteChoice::Multiple ? quint8(FunctionCode::WriteMultipleCoils)
                                               : quint8(FunctionCode::WriteSingleCoil);
    case ModbusTable::HoldingRegisters:
        switch (choice) {
        case WriteChoice::Automatic:
            return registerCount == 1 ? quint8(FunctionCode::WriteSingleRegister)
                                      : quint8(FunctionCode::WriteMultipleRegisters);
        case WriteChoice::Single:
            return registerCount == 1 ? quint8(FunctionCode::WriteSingleRegister) : quint8(0);
        case WriteChoice::Multiple:
            return quint8(FunctionCode::WriteMultipleRegisters);
        }
        return 0;
    case ModbusTable::DiscreteInputs:
    case ModbusTable::InputRegisters:
        return 0;
    }
    return 0;
}

TableWriteResult TableWrite::registers(int address, const QList<quint16> &words, WriteChoice choice)
{
    const quint8 code = functionFor(ModbusTable::HoldingRegisters, int(words.size()), choice);
    if (code == 0) {
        TableWriteResult result;
        result.error = QStringLiteral("06 (Write Single Register) writes one register, but the value spans %1 "
                                      "registers from %2: choose 10 (Write Multiple Registers)")
                           .arg(words.size())
                           .arg(where(ModbusTable::HoldingRegisters, address));
        return result;
    }
    const QString what = words.size() == 1
        ? QStringLiteral("register %1 = %2").arg(where(ModbusTable::HoldingRegisters, address)).arg(words.constFirst())
        : QStringLiteral("%1 registers from %2").arg(words.size()).arg(where(ModbusTable::HoldingRegisters, address));
    if (code == quint8(FunctionCode::WriteSingleRegister))
        return finish(RequestBuilder::writeSingleRegister(address, words.constFirst()), code, what);
    return finish(RequestBuilder::writeMultipleRegisters(address, words), code, what);
}

TableWriteResult TableWrite::coil(int address, bool on, WriteChoice choice)
{
    const quint8 code = functionFor(ModbusTable::Coils, 1, choice);
    const QString what = QStringLiteral("coil %1 = %2").arg(where(ModbusTable::Coils, address),
                                                            on ? QStringLiteral("ON") : QStringLiteral("OFF"));
    if (code == quint8(FunctionCode::WriteSingleCoil))
        return finish(RequestBuilder::writeSingleCoil(address, on), code, what);
    return finish(RequestBuilder::writeMultipleCoils(address, {on}), code, what);
}

std::optional<bool> TableWrite::coilFromText(QStringView text)
{
    const QString t = text.trimmed().toString().toLower();
    if (t == QLatin1String("1") || t == QLatin1String("on") || t == QLatin1String("true"))
        return true;
    if (t == QLatin1String("0") || t == QLatin1String("off") || t == QLatin1String("false"))
        return false;
    return std::nullopt;
}

} // namespace mbscope
