#include "requestform.h"

#include "common/coretext.h"

#include "addressfield.h"
#include "common/severitystyle.h"

#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"
#include "protocol/hextext.h"
#include "protocol/requestbuilder.h"
#include "protocol/functionspec.h"

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

constexpr int kMaxReadWriteWrite = QuantityLimits::kReadWriteWrite; // 0x17's write quantity (V1.1b3, 6.17)

int quantityMax(int code)
{
    return QuantityLimits::maxQuantity(quint8(code));
}

// Upper-case hex digits, zero-padded to width.
QString hexDigits(int value, int width)
{
    return QStringLiteral("%1").arg(value, width, 16, QLatin1Char('0')).toUpper();
}

quint16 word(const QByteArray &pdu, int at)
{
    return quint16((quint8(pdu.at(at)) << 8) | quint8(pdu.at(at + 1)));
}

// Decimal 0-65535, 0x hex, or a negative number as its 16-bit two's complement.
std::optional<quint16> parseRegister(const QString &text)
{
    const QString t = text.trimmed();
    bool ok = false;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        const uint v = t.mid(2).toUInt(&ok, 16);
        return ok && v <= 0xFFFF ? std::optional<quint16>(quint16(v)) : std::nullopt;
    }
    const int v = t.toInt(&ok, 10);
    if (!ok || v < -32768 || v > 65535)
        return std::nullopt;
    return quint16(v);
}

std::optional<int> parseMask(const QString &text)
{
    QString t = text.trimmed();
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        t = t.mid(2);
    bool ok = false;
    const uint v = t.toUInt(&ok, 16);
    return ok && !t.isEmpty() && v <= 0xFFFF ? std::optional<int>(int(v)) : std::nullopt;
}

} // namespace

RequestForm::RequestForm(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    setFunctionCode(0x03);
}

QList<int> RequestForm::functionCodes()
{
    return {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x0F, 0x10, 0x16, 0x17, 0x18, 0x07, 0x0B, 0x0C, 0x11, 0x2B};
}

void RequestForm::setFunctionCode(int code)
{
    const int index = m_function->findData(code);
    if (index >= 0 && index != m_function->currentIndex())
        m_function->setCurrentIndex(index);
    else if (index >= 0)
        onFunctionChanged();
}

int RequestForm::functionCode() const
{
    return m_function->currentData().toInt();
}

void RequestForm::setFraming(Framing framing)
{
    m_framing = framing;
    onChanged();
}

void RequestForm::setUnitId(int unit)
{
    m_unit = quint8(qBound(0, unit, 255));
    onChanged();
}

bool RequestForm::isFieldVisible(QWidget *field) const
{
    QFormLayout::ItemRole role;
    int row = -1;
    m_form->getWidgetPosition(field == m_quantity ? m_quantityRow : field, &row, &role);
    return row >= 0 && m_form->itemAt(row, QFormLayout::FieldRole)->widget()->isVisibleTo(this);
}

void RequestForm::onFunctionChanged()
{
    const int code = functionCode();
    const FunctionSpec *spec = functionSpec(quint8(code));
    const RequestShape shape = spec ? spec->shape : RequestShape::Bare;
    const bool range = shape == RequestShape::Range || shape == RequestShape::RangeValues;
    const bool readWrite = shape == RequestShape::ReadWrite;
    m_form->setRowVisible(m_address, functionStartsWithAddress(quint8(code)));
    m_form->setRowVisible(m_quantityRow, range || readWrite);
    m_form->setRowVisible(m_coil, code == quint8(FunctionCode::WriteSingleCoil));
    m_form->setRowVisible(m_value, code == quint8(FunctionCode::WriteSingleRegister));
    m_form->setRowVisible(m_andMask, shape == RequestShape::Mask);
    m_form->setRowVisible(m_orMask, shape == RequestShape::Mask);
    m_form->setRowVisible(m_writeAddress, readWrite);
    m_form->setRowVisible(m_writeQuantity, readWrite);
    m_form->setRowVisible(m_values, shape == RequestShape::RangeValues || readWrite);
    m_form->setRowVisible(m_deviceIdCode, shape == RequestShape::Mei);
    m_form->setRowVisible(m_objectId, shape == RequestShape::Mei);

    // The address label says what the address is for this code.
    QString addressLabel = tr("Start &address:");
    if (shape == RequestShape::Single || shape == RequestShape::Mask)
        addressLabel = tr("&Address:");
    else if (readWrite)
        addressLabel = tr("Read &address:");
    else if (shape == RequestShape::Pointer)
        addressLabel = tr("FIFO pointer &address:");
    if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(m_address)))
        label->setText(addressLabel);
    if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(m_quantityRow)))
        label->setText(readWrite ? tr("Read &quantity:") : tr("&Quantity:"));

    const std::optional<ModbusTable> table = ModiconReference::tableOf(quint8(code));
    m_address->setTable(shape == RequestShape::Pointer ? std::optional<ModbusTable>(ModbusTable::HoldingRegisters) : table);
    m_writeAddress->setTable(ModbusTable::HoldingRegisters);
    if (spec && spec->maxQuantity > 0)
        m_quantityLimit->setText(tr("1-%1 %2 (V1.1b3)").arg(spec->maxQuantity).arg(fieldText(spec->unit)));
    m_values->horizontalHeaderItem(1)->setText(isCoilTable() ? tr("Coil") : tr("Value"));
    m_values->setRowCount(0); // the other kind of value: start again
    resizeValueTable();
    onChanged();
}

bool RequestForm::isCoilTable() const
{
    return functionCode() == 0x0F;
}

int RequestForm::writeCount() const
{
    // A quantity the specification refuses keeps the table as it was: build() says why.
    const int code = functionCode();
    const int count = code == 0x17 ? m_writeQuantity->value() : m_quantity->value();
    const int max = code == 0x17 ? kMaxReadWriteWrite : quantityMax(code);
    if (code != 0x0F && code != 0x10 && code != 0x17)
        return 0;
    return count >= 1 && count <= max ? count : int(m_values->rowCount());
}

QString RequestForm::quantityError(const QString &label, int quantity, int max, const char *unit) const
{
    if (quantity >= 1 && quantity <= max)
        return {};
    return tr("%1 %2 is refused: %3 takes 1-%4 %5 in one request (Modbus V1.1b3)")
        .arg(label)
        .arg(quantity)
        .arg(fieldText(functionName(quint8(functionCode()))))
        .arg(max)
        .arg(fieldText(unit));
}

void RequestForm::resizeValueTable()
{
    const int rows = writeCount();
    const int before = m_values->rowCount();
    if (rows == before)
        return;
    const QSignalBlocker block(m_values);
    m_values->setRowCount(rows);
    for (int row = before; row < rows; ++row) {
        auto *address = new QTableWidgetItem;
        address->setFlags(Qt::ItemIsEnabled);
        m_values->setItem(row, 0, address);
        auto *value = new QTableWidgetItem;
        if (isCoilTable()) {
            value->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            value->setCheckState(Qt::Unchecked);
            value->setText(tr("OFF"));
        } else {
            value->setText(QStringLiteral("0"));
        }
        m_values->setItem(row, 1, value);
    }
    updateTableAddresses();
}

void RequestForm::updateTableAddresses()
{
    const int code = functionCode();
    const std::optional<int> start = code == 0x17 ? m_writeAddress->address() : m_address->address();
    const ModbusTable table = code == 0x0F ? ModbusTable::Coils : ModbusTable::HoldingRegisters;
    const QSignalBlocker block(m_values);
    for (int row = 0; row < m_values->rowCount(); ++row) {
        QTableWidgetItem *item = m_values->item(row, 0);
        if (!item)
            continue;
        if (!start || *start + row > 65535) {
            item->setText(QStringLiteral("+%1").arg(row));
            continue;
        }
        const ModiconReference ref(table, quint16(*start + row));
        item->setText(QStringLiteral("%1  (%2)").arg(*start + row).arg(ref.hasFiveDigitForm() ? ref.fiveDigit() : ref.sixDigit()));
    }
}

QList<quint16> RequestForm::registerValues(QStringList *errors) const
{
    QList<quint16> values;
    for (int row = 0; row < m_values->rowCount(); ++row) {
        const QString text = m_values->item(row, 1) ? m_values->item(row, 1)->text() : QString();
        const std::optional<quint16> v = parseRegister(text);
        if (!v)
            errors->append(tr("value in row %1: '%2' is not a register value (0-65535, -32768..-1 or 0x0000-0xFFFF)")
                               .arg(row + 1)
                               .arg(text));
        values.append(v.value_or(0));
    }
    return values;
}

QList<bool> RequestForm::coilValues() const
{
    QList<bool> values;
    for (int row = 0; row < m_values->rowCount(); ++row)
        values.append(m_values->item(row, 1) && m_values->item(row, 1)->checkState() == Qt::Checked);
    return values;
}

void RequestForm::setRegisterValues(const QList<quint16> &values)
{
    QSpinBox *count = functionCode() == 0x17 ? m_writeQuantity : m_quantity;
    count->setValue(int(values.size()));
    resizeValueTable();
    const QSignalBlocker block(m_values);
    for (int row = 0; row < values.size() && row < m_values->rowCount(); ++row)
        m_values->item(row, 1)->setText(QString::number(values.at(row)));
    onChanged();
}

void RequestForm::setCoilValues(const QList<bool> &values)
{
    m_quantity->setValue(int(values.size()));
    resizeValueTable();
    const QSignalBlocker block(m_values);
    for (int row = 0; row < values.size() && row < m_values->rowCount(); ++row) {
        m_values->item(row, 1)->setCheckState(values.at(row) ? Qt::Checked : Qt::Unchecked);
        m_values->item(row, 1)->setText(values.at(row) ? tr("ON") : tr("OFF"));
    }
    onChanged();
}

BuildResult RequestForm::build() const
{
    BuildResult failed;
    const int code = functionCode();
    const std::optional<int> address = m_address->address();
    const bool needsAddress = m_form->isRowVisible(m_address);
    if (needsAddress && !address)
        failed.errors.append({QStringLiteral("address"), tr("address: %1").arg(m_address->error())});
    const int a = address.value_or(0);
    const int q = m_quantity->value();
    const FunctionSpec *spec = functionSpec(quint8(code));
    if (m_form->isRowVisible(m_quantityRow) && spec && spec->maxQuantity > 0) {
        const QString why = quantityError(code == 0x17 ? tr("read quantity") : tr("quantity"), q, spec->maxQuantity, spec->unit);
        if (!why.isEmpty())
            failed.errors.append({QStringLiteral("quantity"), why});
    }
    if (code == 0x17) {
        const QString why = quantityError(tr("write quantity"), m_writeQuantity->value(), kMaxReadWriteWrite, "registers");
        if (!why.isEmpty())
            failed.errors.append({QStringLiteral("writeQuantity"), why});
    }
    switch (code) {
    case 0x01: return failed.isValid() ? RequestBuilder::readCoils(a, q) : failed;
    case 0x02: return failed.isValid() ? RequestBuilder::readDiscreteInputs(a, q) : failed;
    case 0x03: return failed.isValid() ? RequestBuilder::readHoldingRegisters(a, q) : failed;
    case 0x04: return failed.isValid() ? RequestBuilder::readInputRegisters(a, q) : failed;
    case 0x05: return failed.isValid() ? RequestBuilder::writeSingleCoil(a, m_coil->isChecked()) : failed;
    case 0x06: {
        const std::optional<quint16> value = parseRegister(m_value->text());
        if (!value)
            failed.errors.append({QStringLiteral("value"), tr("value '%1' is not a register value (0-65535, -32768..-1 or 0x0000-0xFFFF)").arg(m_value->text())});
        return failed.isValid() ? RequestBuilder::writeSingleRegister(a, *value) : failed;
    }
    case 0x0F: return failed.isValid() ? RequestBuilder::writeMultipleCoils(a, coilValues()) : failed;
    case 0x10: {
        QStringList errors;
        const QList<quint16> values = registerValues(&errors);
        for (const QString &e : errors)
            failed.errors.append({QStringLiteral("values"), e});
        return failed.isValid() ? RequestBuilder::writeMultipleRegisters(a, values) : failed;
    }
    case 0x16: {
        const std::optional<int> andMask = parseMask(m_andMask->text());
        const std::optional<int> orMask = parseMask(m_orMask->text());
        if (!andMask)
            failed.errors.append({QStringLiteral("andMask"), tr("AND mask '%1' is not a 16-bit hex value (0x0000-0xFFFF)").arg(m_andMask->text())});
        if (!orMask)
            failed.errors.append({QStringLiteral("orMask"), tr("OR mask '%1' is not a 16-bit hex value (0x0000-0xFFFF)").arg(m_orMask->text())});
        return failed.isValid() ? RequestBuilder::maskWriteRegister(a, *andMask, *orMask) : failed;
    }
    case 0x17: {
        const std::optional<int> writeAddress = m_writeAddress->address();
        if (!writeAddress)
            failed.errors.append({QStringLiteral("writeAddress"), tr("write address: %1").arg(m_writeAddress->error())});
        QStringList errors;
        const QList<quint16> values = registerValues(&errors);
        for (const QString &e : errors)
            failed.errors.append({QStringLiteral("values"), e});
        return failed.isValid() ? RequestBuilder::readWriteMultipleRegisters(a, q, *writeAddress, values) : failed;
    }
    case 0x18: return failed.isValid() ? RequestBuilder::readFifoQueue(a) : failed;
    case 0x07: return RequestBuilder::readExceptionStatus();
    case 0x0B: return RequestBuilder::getCommEventCounter();
    case 0x0C: return RequestBuilder::getCommEventLog();
    case 0x11: return RequestBuilder::reportServerId();
    case 0x2B:
        if (m_objectId->value() > 0xFF) {
            failed.errors.append({QStringLiteral("objectId"), tr("object id 0x%1 is refused: an object id is one byte, 0x00-0xFF")
                                                                  .arg(hexDigits(m_objectId->value(), 2))});
            return failed;
        }
        return RequestBuilder::readDeviceIdentification(m_deviceIdCode->currentData().toInt(), m_objectId->value());
    default: break;
    }
    failed.errors.append({QStringLiteral("function"), tr("function %1 has no form").arg(code)});
    return failed;
}

QByteArray RequestForm::bytes() const
{
    const BuildResult result = build();
    if (!result.isValid())
        return {};
    AduOptions options;
    options.framing = m_framing;
    options.unitId = m_unit;
    options.transactionId = 1;
    return AduBuilder::complete(result.pdu, options);
}

QString RequestForm::errorText() const
{
    const BuildResult result = build();
    QStringList messages;
    for (const BuildError &e : result.errors)
        messages.append(e.message);
    return messages.join(QLatin1Char('\n'));
}

QString RequestForm::previewText() const
{
    return m_previewLabel->text();
}

void RequestForm::onChanged()
{
    m_errorLabel->setText(errorText());
    m_errorLabel->setVisible(!m_errorLabel->text().isEmpty());
    const QByteArray adu = bytes();
    m_previewLabel->setText(adu.isEmpty() ? QString()
                                          : tr("Bytes: %1  (%2, unit %3)")
                                                .arg(HexText::format(adu), framingName(m_framing).toUpper())
                                                .arg(m_unit));
    m_previewLabel->setVisible(!adu.isEmpty());
    if (!m_filling)
        Q_EMIT changed();
}

bool RequestForm::setFromPdu(const QByteArray &pdu)
{
    if (pdu.isEmpty())
        return false;
    const int code = quint8(pdu.at(0));
    const int size = int(pdu.size());
    if (!functionCodes().contains(code))
        return false;
    // Check the whole shape first: a PDU the form cannot show leaves every field as it was.
    bool ok = false;
    switch (code) {
    case 0x01: case 0x02: case 0x03: case 0x04:
        ok = size == 5 && word(pdu, 3) >= 1 && word(pdu, 3) <= quantityMax(code);
        break;
    case 0x05: ok = size == 5 && (word(pdu, 3) == 0xFF00 || word(pdu, 3) == 0x0000); break;
    case 0x06: case 0x16: ok = size == (code == 0x06 ? 5 : 7); break;
    case 0x0F:
        ok = size >= 6 && word(pdu, 3) >= 1 && word(pdu, 3) <= quantityMax(code) && quint8(pdu.at(5)) == (word(pdu, 3) + 7) / 8
             && size == 6 + quint8(pdu.at(5));
        break;
    case 0x10:
        ok = size >= 6 && word(pdu, 3) >= 1 && word(pdu, 3) <= quantityMax(code) && quint8(pdu.at(5)) == 2 * word(pdu, 3)
             && size == 6 + quint8(pdu.at(5));
        break;
    case 0x17:
        ok = size >= 10 && word(pdu, 3) >= 1 && word(pdu, 3) <= QuantityLimits::kReadRegisters && word(pdu, 7) >= 1 && word(pdu, 7) <= kMaxReadWriteWrite
             && quint8(pdu.at(9)) == 2 * word(pdu, 7) && size == 10 + quint8(pdu.at(9));
        break;
    case 0x18: ok = size == 3; break;
    case 0x2B: ok = size == 4 && quint8(pdu.at(1)) == 0x0E && pdu.at(2) >= 1 && pdu.at(2) <= 4; break;
    default: ok = size == 1; break;
    }
    if (!ok)
        return false;

    m_filling = true;
    setFunctionCode(code);
    if (size >= 3 && functionStartsWithAddress(quint8(code)))
        m_address->setAddress(word(pdu, 1));
    switch (code) {
    case 0x01: case 0x02: case 0x03: case 0x04: m_quantity->setValue(word(pdu, 3)); break;
    case 0x05: m_coil->setChecked(word(pdu, 3) == 0xFF00); break;
    case 0x06: m_value->setText(QString::number(word(pdu, 3))); break;
    case 0x16:
        m_andMask->setText(QStringLiteral("0x") + hexDigits(word(pdu, 3), 4));
        m_orMask->setText(QStringLiteral("0x") + hexDigits(word(pdu, 5), 4));
        break;
    case 0x0F: {
        QList<bool> coils;
        for (int i = 0; i < word(pdu, 3); ++i)
            coils.append((quint8(pdu.at(6 + i / 8)) >> (i % 8)) & 1);
        setCoilValues(coils);
        break;
    }
    case 0x10: {
        QList<quint16> values;
        for (int i = 0; i < word(pdu, 3); ++i)
            values.append(word(pdu, 6 + 2 * i));
        setRegisterValues(values);
        break;
    }
    case 0x17: {
        m_quantity->setValue(word(pdu, 3));
        m_writeAddress->setAddress(word(pdu, 5));
        QList<quint16> values;
        for (int i = 0; i < word(pdu, 7); ++i)
            values.append(word(pdu, 10 + 2 * i));
        setRegisterValues(values);
        break;
    }
    case 0x2B:
        m_deviceIdCode->setCurrentIndex(m_deviceIdCode->findData(int(pdu.at(2))));
        m_objectId->setValue(quint8(pdu.at(3)));
        break;
    default: break;
    }
    m_filling = false;
    onChanged();
    return true;
}

} // namespace mbscope
