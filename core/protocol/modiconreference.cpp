#include "modiconreference.h"

#include "hexformat.h"

namespace mbscope {

namespace {

constexpr FunctionCode kReadCoils[] = {FunctionCode::ReadCoils};
constexpr FunctionCode kWriteCoils[] = {FunctionCode::WriteSingleCoil, FunctionCode::WriteMultipleCoils};
constexpr FunctionCode kReadDiscreteInputs[] = {FunctionCode::ReadDiscreteInputs};
constexpr FunctionCode kReadInputRegisters[] = {FunctionCode::ReadInputRegisters};
constexpr FunctionCode kReadHolding[] = {FunctionCode::ReadHoldingRegisters, FunctionCode::ReadWriteMultipleRegisters};
constexpr FunctionCode kWriteHolding[] = {FunctionCode::WriteSingleRegister, FunctionCode::WriteMultipleRegisters,
                                          FunctionCode::MaskWriteRegister, FunctionCode::ReadWriteMultipleRegisters};

std::optional<ModbusTable> tableOfDigit(QChar digit)
{
    switch (digit.unicode()) {
    case u'0': return ModbusTable::Coils;
    case u'1': return ModbusTable::DiscreteInputs;
    case u'3': return ModbusTable::InputRegisters;
    case u'4': return ModbusTable::HoldingRegisters;
    default: return std::nullopt;
    }
}

QString quoted(QStringView text)
{
    return QLatin1Char('\'') + text.toString() + QLatin1Char('\'');
}

// "40001-49999" / "400001-465536"
QString fiveDigitRange(ModbusTable table)
{
    const QString d = QString::number(ModiconReference::tableDigit(table));
    return d + QLatin1String("0001-") + d + QLatin1String("9999");
}

QString sixDigitRange(ModbusTable table)
{
    const QString d = QString::number(ModiconReference::tableDigit(table));
    return d + QLatin1String("00001-") + d + QLatin1String("65536");
}

ModiconReferenceResult failed(QString why)
{
    ModiconReferenceResult result;
    result.error = std::move(why);
    return result;
}

ModiconReferenceResult success(ModbusTable table, int number, ModiconReference::Form form)
{
    ModiconReferenceResult result;
    result.reference = ModiconReference(table, quint16(number - 1));
    result.form = form;
    result.ok = true;
    return result;
}

} // namespace

QString ModiconReference::fiveDigit() const
{
    if (!hasFiveDigitForm())
        return QString();
    return QString::number(tableDigit()) + QString::number(number()).rightJustified(4, QLatin1Char('0'));
}

QString ModiconReference::sixDigit() const
{
    return QString::number(tableDigit()) + QString::number(number()).rightJustified(5, QLatin1Char('0'));
}

QString ModiconReference::describe() const
{
    QString text = QStringLiteral("PDU address %1 (%2), %3 %4, Modicon ")
                       .arg(m_address)
                       .arg(hexWord(m_address))
                       .arg(QLatin1String(numberName(m_table)))
                       .arg(number());
    if (hasFiveDigitForm())
        return text + fiveDigit() + QLatin1String(" / ") + sixDigit();
    return text + sixDigit() + QLatin1String(" (no five-digit form: ") + fiveDigitRange(m_table)
        + QLatin1String(" reach PDU addresses 0-9998 only)");
}

QString ModiconReference::addressHint(qint64 address)
{
    if (address < 10001 || address > 465536)
        return {};
    const ModiconReferenceResult r = parse(QString::number(address));
    if (!r.ok)
        return {};
    return QStringLiteral("%1 looks like a Modicon reference; its PDU address is %2 (0x%3)")
        .arg(address)
        .arg(r.reference.address())
        .arg(QString::number(r.reference.address(), 16).toUpper().rightJustified(4, QLatin1Char('0')));
}

ModiconReferenceResult ModiconReference::parse(QStringView text)
{
    const QStringView t = text.trimmed();
    if (t.isEmpty()) {
        return failed(QStringLiteral("the reference is empty: expected a Modicon reference such as 40001 "
                                     "(five digits) or 400001 (six)"));
    }

    const bool prefixed = t.size() >= 2 && (t[1] == u'x' || t[1] == u'X');
    const QStringView digits = prefixed ? t.sliced(2) : t;
    for (qsizetype i = 0; i < t.size(); ++i) {
        if (prefixed && i == 1)
            continue;
        if (t[i] < u'0' || t[i] > u'9') {
            return failed(quoted(t) + QStringLiteral(" is not a reference: '%1' at character %2 is not a digit "
                                                     "(expected e.g. 40001, 400001 or 4x1)")
                                          .arg(t[i])
                                          .arg(i + 1));
        }
    }

    const std::optional<ModbusTable> table = tableOfDigit(t[0]);
    if (!table) {
        QString why = quoted(t) + QStringLiteral(" is not a reference: the leading digit %1 names no table "
                                                 "(0 coils, 1 discrete inputs, 3 input registers, "
                                                 "4 holding registers)")
                                      .arg(t[0]);
        if (t[0] == u'6')
            why += QLatin1String("; 6xxxx is Modicon's extended memory, read as file records (functions 20 "
                                 "and 21), which has no table address");
        return failed(why);
    }
    const QString name = QLatin1String(tableName(*table));

    if (prefixed) {
        const QString prefix = t.first(2).toString();
        if (digits.isEmpty()) {
            return failed(quoted(t) + QLatin1String(" is not a reference: a number (1-65536) must follow ")
                          + prefix);
        }
        // Leading zeros are allowed ("4x0122"); the count of digits is no limit, the value is.
        const QStringView significant = [&] {
            qsizetype z = 0;
            while (z < digits.size() - 1 && digits[z] == u'0')
                ++z;
            return digits.sliced(z);
        }();
        const int number = significant.size() > 5 ? 65537 : significant.toInt();
        if (number == 0)
            return failed(quoted(t) + QLatin1String(" is not a reference: ") + name + QLatin1String(" start at ")
                          + prefix + QLatin1Char('1'));
        if (number > 65536) {
            return failed(quoted(t) + QLatin1String(" is out of range: ") + name + QLatin1String(" end at ")
                          + prefix + QLatin1String("65536 (PDU address 65535)"));
        }
        return success(*table, number, Form::Prefixed);
    }

    if (t.size() != 5 && t.size() != 6) {
        return failed(quoted(t) + QStringLiteral(" is not a reference: it has %1; %2 references have "
                                                 "five digits (%3) or six (%4)")
                                      .arg(t.size() == 1 ? QStringLiteral("1 digit")
                                                         : QStringLiteral("%1 digits").arg(t.size()))
                                      .arg(name.chopped(1))
                                      .arg(fiveDigitRange(*table), sixDigitRange(*table)));
    }
    const int number = t.sliced(1).toInt();
    const QChar d = t[0];
    if (number == 0) {
        return failed(quoted(t) + QLatin1String(" is not a reference: ") + name + QLatin1String(" start at ")
                      + d + (t.size() == 5 ? QLatin1String("0001") : QLatin1String("00001")));
    }
    if (t.size() == 5)
        return success(*table, number, Form::FiveDigit);
    if (number > 65536) {
        return failed(quoted(t) + QLatin1String(" is out of range: ") + name + QLatin1String(" end at ") + d
                      + QLatin1String("65536 (PDU address 65535)"));
    }
    return success(*table, number, Form::SixDigit);
}

ModiconReferenceResult ModiconReference::fromNumber(ModbusTable table, int number)
{
    if (number < 1 || number > 65536) {
        return failed(QStringLiteral("%1 %2 is out of range: %3 are numbered 1-65536 (PDU addresses 0-65535)")
                          .arg(QLatin1String(numberName(table)))
                          .arg(number)
                          .arg(QLatin1String(tableName(table))));
    }
    return success(table, number, number <= 9999 ? Form::FiveDigit : Form::SixDigit);
}

const char *ModiconReference::tableName(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coils: return QT_TRANSLATE_NOOP("mbscope::Field", "coils");
    case ModbusTable::DiscreteInputs: return QT_TRANSLATE_NOOP("mbscope::Field", "discrete inputs");
    case ModbusTable::InputRegisters: return QT_TRANSLATE_NOOP("mbscope::Field", "input registers");
    case ModbusTable::HoldingRegisters: return QT_TRANSLATE_NOOP("mbscope::Field", "holding registers");
    }
    return QT_TRANSLATE_NOOP("mbscope::Field", "holding registers");
}

const char *ModiconReference::numberName(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coils: return "coil number";
    case ModbusTable::DiscreteInputs: return "discrete input number";
    case ModbusTable::InputRegisters:
    case ModbusTable::HoldingRegisters: return "register number";
    }
    return "register number";
}

std::span<const FunctionCode> ModiconReference::readFunctions(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coils: return kReadCoils;
    case ModbusTable::DiscreteInputs: return kReadDiscreteInputs;
    case ModbusTable::InputRegisters: return kReadInputRegisters;
    case ModbusTable::HoldingRegisters: return kReadHolding;
    }
    return {};
}

std::span<const FunctionCode> ModiconReference::writeFunctions(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coils: return kWriteCoils;
    case ModbusTable::HoldingRegisters: return kWriteHolding;
    case ModbusTable::DiscreteInputs:
    case ModbusTable::InputRegisters: return {};
    }
    return {};
}

std::optional<ModbusTable> ModiconReference::tableOf(quint8 functionCode)
{
    switch (FunctionCode(functionCode)) {
    case FunctionCode::ReadCoils:
    case FunctionCode::WriteSingleCoil:
    case FunctionCode::WriteMultipleCoils:
        return ModbusTable::Coils;
    case FunctionCode::ReadDiscreteInputs:
        return ModbusTable::DiscreteInputs;
    case FunctionCode::ReadInputRegisters:
        return ModbusTable::InputRegisters;
    case FunctionCode::ReadHoldingRegisters:
    case FunctionCode::WriteSingleRegister:
    case FunctionCode::WriteMultipleRegisters:
    case FunctionCode::MaskWriteRegister:
    case FunctionCode::ReadWriteMultipleRegisters:
        return ModbusTable::HoldingRegisters;
    default:
        return std::nullopt;
    }
}

} // namespace mbscope
