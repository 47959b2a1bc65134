#include "readanswer.h"

#include "functioncode.h"
#include "hexformat.h"

namespace mbscope {

namespace {

ReadAnswerResult failed(QString why)
{
    ReadAnswerResult result;
    result.error = std::move(why);
    return result;
}

int word(QByteArrayView bytes, qsizetype at)
{
    return (quint8(bytes[at]) << 8) | quint8(bytes[at + 1]);
}

QString functionText(quint8 code)
{
    return hexByte(code) + QLatin1String(" (") + QLatin1String(functionName(code)) + QLatin1Char(')');
}

} // namespace

std::optional<RegisterValue> ReadAnswer::valueAt(int index, RegisterFormat format) const
{
    const int n = format.registerCount();
    if (index < 0 || index % n != 0 || index + n > registers.size())
        return std::nullopt;
    const RegisterValueResult r =
        RegisterValue::fromRegisters(std::span<const quint16>(registers.constData() + index, size_t(n)), format);
    return r.ok ? std::optional<RegisterValue>(r.value) : std::nullopt;
}

QString ReadAnswer::referenceText(const ModiconReference &reference)
{
    return reference.hasFiveDigitForm() ? reference.fiveDigit() : reference.sixDigit();
}

QString ReadAnswer::addressText(int address)
{
    return QString::number(address) + QLatin1String(" (") + hexWord(quint64(address)) + QLatin1Char(')');
}

ReadAnswerResult ReadAnswer::fromPdus(QByteArrayView request, QByteArrayView response)
{
    if (request.isEmpty())
        return failed(QStringLiteral("the request is empty: expected a read (01, 02, 03, 04 or 17)"));
    const auto code = quint8(request[0]);
    switch (FunctionCode(code)) {
    case FunctionCode::ReadCoils:
    case FunctionCode::ReadDiscreteInputs:
    case FunctionCode::ReadHoldingRegisters:
    case FunctionCode::ReadInputRegisters:
    case FunctionCode::ReadWriteMultipleRegisters:
        break;
    default:
        return failed(QLatin1String("the request is function ") + functionText(code)
                      + QLatin1String(", not a read of a table (01, 02, 03, 04 or 17)"));
    }
    // V1.1b3 6.1-6.4 and 6.17: the starting address and the quantity follow the function code.
    if (request.size() < 5) {
        return failed(QStringLiteral("the request is %1 bytes long: a read carries the function code, the "
                                     "starting address and the quantity (5 bytes)")
                          .arg(request.size()));
    }
    return fromResponse(code, word(request, 1), word(request, 3), response);
}

ReadAnswerResult ReadAnswer::fromResponse(quint8 code, int address, int quantity, QByteArrayView response)
{
    const std::optional<ModbusTable> table = ModiconReference::tableOf(code);
    if (!table)
        return failed(QLatin1String("function ") + functionText(code) + QLatin1String(" reads no table"));
    if (response.isEmpty())
        return failed(QStringLiteral("the answer is empty"));
    const auto answered = quint8(response[0]);
    if (answered == (code | 0x80)) {
        const quint8 exception = response.size() > 1 ? quint8(response[1]) : 0;
        return failed(QLatin1String("the answer is exception ") + hexByte(exception) + QLatin1String(" (")
                      + QLatin1String(exceptionName(exception)) + QLatin1String(") to ") + functionText(code));
    }
    if (answered != code) {
        return failed(QLatin1String("the answer is function ") + functionText(answered) + QLatin1String(" to a ")
                      + functionText(code) + QLatin1String(" request"));
    }
    if (response.size() < 2)
        return failed(QStringLiteral("the answer ends after the function code: the byte count is missing (offset 1)"));
    const int byteCount = quint8(response[1]);
    const qsizetype following = response.size() - 2;
    if (following != byteCount) {
        return failed(QStringLiteral("the byte count (offset 1 of the answer) says %1 bytes but %2 follow it")
                          .arg(byteCount)
                          .arg(following));
    }
    ReadAnswer a;
    a.table = *table;
    a.functionCode = code;
    a.address = address;
    a.quantity = quantity;
    const QByteArrayView data = response.sliced(2);
    if (a.isBits()) {
        const int expected = (quantity + 7) / 8;
        if (byteCount != expected) {
            return failed(QStringLiteral("the answer holds %1 data bytes but %2 %3 take %4")
                              .arg(byteCount)
                              .arg(quantity)
                              .arg(QLatin1String(quantity == 1 ? "bit" : "bits"))
                              .arg(expected));
        }
        a.bits.reserve(quantity);
        // V1.1b3 6.1: the first bit asked is the least significant bit of the first data byte.
        for (int i = 0; i < quantity; ++i)
            a.bits.append((quint8(data[i / 8]) >> (i % 8)) & 1);
    } else {
        if (byteCount != 2 * quantity) {
            return failed(QStringLiteral("the answer holds %1 data bytes (%2 registers) but %3 registers were asked")
                              .arg(byteCount)
                              .arg(QString::number(byteCount / 2.0))
                              .arg(quantity));
        }
        a.registers.reserve(quantity);
        for (int i = 0; i < quantity; ++i)
            a.registers.append(quint16(word(data, 2 * i)));
    }
    if (address < 0 || address + a.count() > 0x10000) {
        return failed(QStringLiteral("the read from PDU address %1 for %2 values runs beyond address 65535")
                          .arg(address)
                          .arg(a.count()));
    }
    ReadAnswerResult result;
    result.answer = std::move(a);
    result.ok = true;
    return result;
}

} // namespace mbscope
