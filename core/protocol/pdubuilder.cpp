#include "pdubuilder.h"

#include "functioncode.h"
#include "hexformat.h"

namespace mbscope {

PduBuilder::PduBuilder(quint8 function)
    : m_function(function)
{
    m_pdu.reserve(16);
    m_pdu.append(char(function));
}

const char *PduBuilder::functionName() const
{
    return mbscope::functionName(m_function);
}

void PduBuilder::appendU16(int value)
{
    m_pdu.append(char(quint8(value >> 8)));
    m_pdu.append(char(quint8(value)));
}

void PduBuilder::appendBits(const QList<bool> &values)
{
    const int byteCount = int((values.size() + 7) / 8);
    appendU8(byteCount);
    for (int i = 0; i < byteCount; ++i) {
        int packed = 0;
        for (int bit = 0; bit < 8 && i * 8 + bit < values.size(); ++bit) {
            if (values[i * 8 + bit])
                packed |= 1 << bit;
        }
        appendU8(packed);
    }
}

void PduBuilder::appendRegisters(const QList<quint16> &values)
{
    appendU8(int(values.size() * 2));
    for (quint16 value : values)
        appendU16(value);
}

BuildResult PduBuilder::startAndQuantity(quint8 function, int startAddress, int quantity, int maxQuantity,
                                         const char *verb, const char *unit)
{
    PduBuilder b(function);
    b.checkAddress(QStringLiteral("startAddress"), QStringLiteral("start address"), startAddress);
    b.checkQuantity(QStringLiteral("quantity"), QStringLiteral("quantity"), quantity, maxQuantity, verb, unit);
    b.checkSpan(QStringLiteral("quantity"), QStringLiteral("start address"), startAddress, quantity);
    b.appendU16(startAddress);
    b.appendU16(quantity);
    return b.finish();
}

void PduBuilder::addError(const QString &parameter, const QString &message)
{
    m_errors.append(BuildError{parameter, message});
}

QString PduBuilder::hex(qint64 value, int digits)
{
    return mbscope::hex(quint64(value), digits);
}

bool PduBuilder::checkRange(const QString &parameter, const QString &label, qint64 value, qint64 min,
                            qint64 max, const QString &rule)
{
    if (value >= min && value <= max)
        return true;
    addError(parameter, QStringLiteral("%1 %2 is out of range: %3").arg(label).arg(value).arg(rule));
    return false;
}

bool PduBuilder::checkAddress(const QString &parameter, const QString &label, qint64 value)
{
    return checkRange(parameter, label, value, 0, 0xFFFF,
                      QStringLiteral("%1 addresses are 0-65535 (0x0000-0xFFFF)")
                          .arg(QString::fromLatin1(functionName())));
}

bool PduBuilder::checkU16(const QString &parameter, const QString &label, qint64 value)
{
    return checkRange(parameter, label, value, 0, 0xFFFF,
                      QStringLiteral("%1 takes a 16-bit value, 0-65535 (0x0000-0xFFFF)")
                          .arg(QString::fromLatin1(functionName())));
}

bool PduBuilder::checkU8(const QString &parameter, const QString &label, qint64 value)
{
    return checkRange(parameter, label, value, 0, 0xFF,
                      QStringLiteral("%1 takes a byte, 0-255 (0x00-0xFF)").arg(QString::fromLatin1(functionName())));
}

bool PduBuilder::checkQuantity(const QString &parameter, const QString &label, qint64 value, int max,
                               const char *verb, const char *unit)
{
    return checkRange(parameter, label, value, 1, max,
                      QStringLiteral("%1 %2 1-%3 %4")
                          .arg(QString::fromLatin1(functionName()), QString::fromLatin1(verb))
                          .arg(max)
                          .arg(QString::fromLatin1(unit)));
}

bool PduBuilder::checkSpan(const QString &parameter, const QString &startLabel, qint64 start, qint64 quantity)
{
    // Only meaningful once start and quantity are each valid; their own checks report otherwise.
    if (start < 0 || start > 0xFFFF || quantity < 1)
        return true;
    const qint64 last = start + quantity - 1;
    if (last <= 0xFFFF)
        return true;
    addError(parameter, QStringLiteral("%1 %2 with quantity %3 ends at %4, past the last address 65535: "
                                       "%5 can only reach addresses 0-65535")
                            .arg(startLabel)
                            .arg(start)
                            .arg(quantity)
                            .arg(last)
                            .arg(QString::fromLatin1(functionName())));
    return false;
}

bool PduBuilder::checkFits(const QString &parameter, const QString &label, qint64 bytes, int reserve)
{
    const qint64 room = MaxPduSize - size() - reserve;
    if (bytes <= room)
        return true;
    addError(parameter, QStringLiteral("%1 of %2 bytes does not fit: a PDU holds at most 253 bytes, which "
                                       "leaves %3 bytes for it (function code %4, %5)")
                            .arg(label)
                            .arg(bytes)
                            .arg(qMax<qint64>(room, 0))
                            .arg(hex(m_function, 2), QString::fromLatin1(functionName())));
    return false;
}

BuildResult PduBuilder::finish()
{
    if (m_errors.isEmpty() && m_pdu.size() > MaxPduSize) {
        addError(QStringLiteral("pdu"), QStringLiteral("the PDU would be %1 bytes: a Modbus PDU holds at most 253 bytes "
                                                       "(V1.1b3, 4.1)")
                                            .arg(m_pdu.size()));
    }
    BuildResult result;
    if (m_errors.isEmpty())
        result.pdu = std::move(m_pdu);
    else
        result.errors = std::move(m_errors);
    return result;
}

} // namespace mbscope
