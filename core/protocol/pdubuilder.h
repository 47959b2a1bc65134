#pragma once

#include "buildresult.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

namespace mbscope {

// The shared mechanics of RequestBuilder and ResponseBuilder: appends big-endian fields to a
// PDU, checks parameters against the specification's limits and collects every problem with
// one wording, so that all builders speak alike. Not meant for use outside the builders.
class PduBuilder
{
public:
    // V1.1b3, 4.1: the PDU is limited to 253 bytes by the serial line ADU (256 bytes minus
    // address and CRC); every framing uses the same bound.
    static constexpr int MaxPduSize = 253;
    static constexpr int MaxDataSize = MaxPduSize - 1;

    explicit PduBuilder(quint8 function);

    [[nodiscard]] quint8 function() const { return m_function; }
    [[nodiscard]] const char *functionName() const;
    [[nodiscard]] int size() const { return int(m_pdu.size()); }
    [[nodiscard]] bool hasErrors() const { return !m_errors.isEmpty(); }

    void appendU8(int value) { m_pdu.append(char(quint8(value))); }
    void appendU16(int value); // big-endian, as every Modbus data item (V1.1b3, 4.2)
    void appendBytes(QByteArrayView bytes) { m_pdu.append(bytes.data(), bytes.size()); }
    // A byte count, then the bits packed 8 to a byte, the first in the low bit of the first byte
    // and the unused high bits of the last byte zero (V1.1b3, 6.1, 6.2, 6.11).
    void appendBits(const QList<bool> &values);
    // A byte count (2 per register), then the registers (V1.1b3, 6.3, 6.4, 6.12, 6.17).
    void appendRegisters(const QList<quint16> &values);

    void addError(const QString &parameter, const QString &message);

    // "<label> <value> is out of range: <rule>", when value is outside [min, max].
    bool checkRange(const QString &parameter, const QString &label, qint64 value, qint64 min,
                    qint64 max, const QString &rule);
    // A 16-bit address (V1.1b3, 4.4: the addressing model is 0-65535).
    bool checkAddress(const QString &parameter, const QString &label, qint64 value);
    // A 16-bit value (register contents, masks).
    bool checkU16(const QString &parameter, const QString &label, qint64 value);
    // An 8-bit value.
    bool checkU8(const QString &parameter, const QString &label, qint64 value);
    // A quantity of items: "<label> <value> is out of range: <Function> <verb> 1-<max> <unit>".
    bool checkQuantity(const QString &parameter, const QString &label, qint64 value, int max,
                       const char *verb, const char *unit);
    // start + quantity must stay within the address space: the last item is at most 65535.
    bool checkSpan(const QString &parameter, const QString &startLabel, qint64 start, qint64 quantity);
    // Data bytes that the PDU can still hold after what has been appended plus reserve bytes.
    bool checkFits(const QString &parameter, const QString &label, qint64 bytes, int reserve = 0);

    // The result: the PDU when nothing is wrong (and it is within 253 bytes), else the errors.
    [[nodiscard]] BuildResult finish();

    // A PDU of start address and quantity, both checked (01-04 requests, 0F/10 responses): verb
    // and unit complete the quantity's rule ("reads", "coils").
    [[nodiscard]] static BuildResult startAndQuantity(quint8 function, int startAddress, int quantity,
                                                      int maxQuantity, const char *verb, const char *unit);

    [[nodiscard]] static QString hex(qint64 value, int digits);

private:
    QByteArray m_pdu;
    QList<BuildError> m_errors;
    quint8 m_function = 0;
};

} // namespace mbscope
