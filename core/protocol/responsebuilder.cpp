#include "responsebuilder.h"
#include "quantitylimits.h"

#include "diagnosticrules.h"
#include "pdubuilder.h"

namespace mbscope {

namespace {

BuildResult readBits(quint8 function, const QList<bool> &values, const char *unit)
{
    PduBuilder b(function);
    if (!b.checkQuantity(QStringLiteral("values"), QStringLiteral("quantity"), values.size(), QuantityLimits::kReadBits, "reads", unit))
        return b.finish();
    b.appendBits(values);
    return b.finish();
}

BuildResult registers(quint8 function, const QList<quint16> &values, const QString &label, int min, int max)
{
    PduBuilder b(function);
    const qint64 quantity = values.size();
    if (!b.checkRange(QStringLiteral("values"), label, quantity, min, max,
                      QStringLiteral("%1 returns %2-%3 registers")
                          .arg(QString::fromLatin1(b.functionName()))
                          .arg(min)
                          .arg(max))) {
        return b.finish();
    }
    b.appendRegisters(values);
    return b.finish();
}

} // namespace

BuildResult ResponseBuilder::readCoils(const QList<bool> &values)
{
    return readBits(0x01, values, "coils");
}

BuildResult ResponseBuilder::readDiscreteInputs(const QList<bool> &values)
{
    return readBits(0x02, values, "discrete inputs");
}

BuildResult ResponseBuilder::readHoldingRegisters(const QList<quint16> &values)
{
    return registers(0x03, values, QStringLiteral("quantity"), 1, QuantityLimits::kReadRegisters);
}

BuildResult ResponseBuilder::readInputRegisters(const QList<quint16> &values)
{
    return registers(0x04, values, QStringLiteral("quantity"), 1, QuantityLimits::kReadRegisters);
}

BuildResult ResponseBuilder::writeSingleCoil(int address, bool on)
{
    // V1.1b3, 6.5: the normal response is an echo of the request.
    return RequestBuilder::writeSingleCoil(address, on);
}

BuildResult ResponseBuilder::writeSingleCoilValue(int address, int value)
{
    return RequestBuilder::writeSingleCoilValue(address, value);
}

BuildResult ResponseBuilder::writeSingleRegister(int address, int value)
{
    // V1.1b3, 6.6: an echo of the request.
    return RequestBuilder::writeSingleRegister(address, value);
}

BuildResult ResponseBuilder::writeMultipleCoils(int startAddress, int quantity)
{
    // V1.1b3, 6.11: the start address and the quantity of coils forced.
    return PduBuilder::startAndQuantity(0x0F, startAddress, quantity, QuantityLimits::kWriteCoils, "writes", "coils");
}

BuildResult ResponseBuilder::writeMultipleRegisters(int startAddress, int quantity)
{
    return PduBuilder::startAndQuantity(0x10, startAddress, quantity, QuantityLimits::kWriteRegisters, "writes", "registers");
}

BuildResult ResponseBuilder::maskWriteRegister(int address, int andMask, int orMask)
{
    // V1.1b3, 6.16: an echo of the request.
    return RequestBuilder::maskWriteRegister(address, andMask, orMask);
}

BuildResult ResponseBuilder::readWriteMultipleRegisters(const QList<quint16> &readValues)
{
    return registers(0x17, readValues, QStringLiteral("read quantity"), 1, QuantityLimits::kReadRegisters);
}

BuildResult ResponseBuilder::readFifoQueue(const QList<quint16> &values)
{
    PduBuilder b(0x18);
    // V1.1b3, 6.18: up to 31 queued registers; a longer queue is answered with exception 03.
    const qint64 count = values.size();
    if (!b.checkRange(QStringLiteral("values"), QStringLiteral("FIFO count"), count, 0, 31,
                      QStringLiteral("Read FIFO Queue returns 0-31 queued registers (a longer queue is answered "
                                     "with exception 03)"))) {
        return b.finish();
    }
    b.appendU16(int(2 + count * 2)); // the byte count is 2 bytes and includes the FIFO count
    b.appendU16(int(count));
    for (quint16 value : values)
        b.appendU16(value);
    return b.finish();
}

BuildResult ResponseBuilder::readFileRecord(const QList<QList<quint16>> &records)
{
    PduBuilder b(0x14);
    const qint64 count = records.size();
    if (!b.checkRange(QStringLiteral("records"), QStringLiteral("sub-response count"), count, 1, 35,
                      QStringLiteral("Read File Record answers 1-35 sub-requests, one sub-response each"))) {
        return b.finish();
    }
    qint64 dataLength = 0;
    for (qsizetype i = 0; i < records.size(); ++i) {
        b.checkRange(QStringLiteral("records[%1]").arg(i), QStringLiteral("record length"), records[i].size(), 1, 124,
                     QStringLiteral("Read File Record returns 1-124 registers per sub-response"));
        dataLength += 2 + 2 * qint64(records[i].size());
    }
    if (!b.hasErrors() && dataLength > PduBuilder::MaxDataSize - 1) {
        b.addError(QStringLiteral("records"),
                   QStringLiteral("response data length %1 is out of range: Read File Record's sub-responses must fit "
                                  "in a 253-byte PDU, at most 251 bytes")
                       .arg(dataLength));
    }
    if (b.hasErrors())
        return b.finish();
    // V1.1b3, 6.14: each sub-response is its length (reference type + data), reference type 6,
    // then the record data.
    b.appendU8(int(dataLength));
    for (const QList<quint16> &record : records) {
        b.appendU8(int(1 + 2 * record.size()));
        b.appendU8(6);
        for (quint16 value : record)
            b.appendU16(value);
    }
    return b.finish();
}

BuildResult ResponseBuilder::writeFileRecord(const QList<FileRecordWrite> &subRequests)
{
    // V1.1b3, 6.15: the normal response is an echo of the request.
    return RequestBuilder::writeFileRecord(subRequests);
}

BuildResult ResponseBuilder::readExceptionStatus(int outputs)
{
    PduBuilder b(0x07);
    b.checkRange(QStringLiteral("outputs"), QStringLiteral("output data"), outputs, 0, 0xFF,
                 QStringLiteral("Read Exception Status returns one byte, 0-255 (0x00-0xFF)"));
    b.appendU8(outputs);
    return b.finish();
}

BuildResult ResponseBuilder::diagnostics(int subFunction, const QByteArray &data)
{
    return diagnosticrules::build(subFunction, data, Direction::Response);
}

BuildResult ResponseBuilder::diagnosticsValue(int subFunction, int value)
{
    PduBuilder b(0x08);
    if (!b.checkRange(QStringLiteral("value"), QStringLiteral("value"), value, 0, 0xFFFF,
                      QStringLiteral("Diagnostics data words are 16-bit, 0-65535 (0x0000-0xFFFF)"))) {
        return b.finish();
    }
    QByteArray data(2, '\0');
    data[0] = char(quint8(value >> 8));
    data[1] = char(quint8(value));
    return diagnostics(subFunction, data);
}

BuildResult ResponseBuilder::getCommEventCounter(bool busy, int eventCount)
{
    PduBuilder b(0x0B);
    b.checkRange(QStringLiteral("eventCount"), QStringLiteral("event count"), eventCount, 0, 0xFFFF,
                 QStringLiteral("Get Comm Event Counter's event count is 16-bit, 0-65535"));
    b.appendU16(busy ? 0xFFFF : 0x0000);
    b.appendU16(eventCount);
    return b.finish();
}

BuildResult ResponseBuilder::getCommEventLog(bool busy, int eventCount, int messageCount, const QByteArray &events)
{
    PduBuilder b(0x0C);
    b.checkRange(QStringLiteral("eventCount"), QStringLiteral("event count"), eventCount, 0, 0xFFFF,
                 QStringLiteral("Get Comm Event Log's event count is 16-bit, 0-65535"));
    b.checkRange(QStringLiteral("messageCount"), QStringLiteral("message count"), messageCount, 0, 0xFFFF,
                 QStringLiteral("Get Comm Event Log's message count is 16-bit, 0-65535"));
    // V1.1b3, 6.10: the event field holds 0-64 bytes, the most recent first.
    b.checkRange(QStringLiteral("events"), QStringLiteral("number of event bytes"), events.size(), 0, 64,
                 QStringLiteral("Get Comm Event Log returns 0-64 event bytes"));
    if (b.hasErrors())
        return b.finish();
    b.appendU8(int(6 + events.size()));
    b.appendU16(busy ? 0xFFFF : 0x0000);
    b.appendU16(eventCount);
    b.appendU16(messageCount);
    b.appendBytes(events);
    return b.finish();
}

BuildResult ResponseBuilder::reportServerId(const QByteArray &serverId, bool running, const QByteArray &additionalData)
{
    PduBuilder b(0x11);
    if (serverId.isEmpty()) {
        b.addError(QStringLiteral("serverId"),
                   QStringLiteral("no server ID: Report Server ID returns a device-specific server ID of at least one "
                                  "byte before the run indicator"));
        return b.finish();
    }
    // V1.1b3, 6.13: byte count, server ID, run indicator (0x00 OFF, 0xFF ON), additional data.
    const qint64 byteCount = serverId.size() + 1 + additionalData.size();
    if (!b.checkFits(QStringLiteral("additionalData"), QStringLiteral("server ID, run indicator and additional data"),
                     byteCount, 1)) {
        return b.finish();
    }
    b.appendU8(int(byteCount));
    b.appendBytes(serverId);
    b.appendU8(running ? 0xFF : 0x00);
    b.appendBytes(additionalData);
    return b.finish();
}

BuildResult ResponseBuilder::readDeviceIdentification(int readDeviceIdCode, int conformityLevel, bool moreFollows,
                                                      int nextObjectId, const QList<DeviceIdObject> &objects)
{
    PduBuilder b(0x2B);
    b.checkRange(QStringLiteral("readDeviceIdCode"), QStringLiteral("read device ID code"), readDeviceIdCode, 1, 4,
                 QStringLiteral("Read Device Identification takes 1-4 (1 basic, 2 regular, 3 extended stream access, "
                                "4 one specific object)"));
    const bool knownLevel = (conformityLevel >= 0x01 && conformityLevel <= 0x03)
        || (conformityLevel >= 0x81 && conformityLevel <= 0x83);
    if (!knownLevel) {
        b.addError(QStringLiteral("conformityLevel"),
                   QStringLiteral("conformity level %1 is not defined: Read Device Identification uses 0x01-0x03 "
                                  "(stream access) or 0x81-0x83 (stream and individual access)")
                       .arg(PduBuilder::hex(conformityLevel, 2)));
    } else if (readDeviceIdCode == 4 && conformityLevel < 0x80) {
        b.addError(QStringLiteral("conformityLevel"),
                   QStringLiteral("conformity level %1 does not allow individual access: a response to read device ID "
                                  "code 4 needs 0x81-0x83")
                       .arg(PduBuilder::hex(conformityLevel, 2)));
    }
    // V1.1b3, 6.21: More Follows is 00 or FF, 00 for an individual access; Next Object Id is
    // meaningful only when more follows, and 00 otherwise.
    if (moreFollows && readDeviceIdCode == 4) {
        b.addError(QStringLiteral("moreFollows"),
                   QStringLiteral("more follows is not allowed for an individual access (read device ID code 4): it "
                                  "must be 0x00"));
    }
    if (moreFollows) {
        b.checkRange(QStringLiteral("nextObjectId"), QStringLiteral("next object ID"), nextObjectId, 0, 0xFF,
                     QStringLiteral("Read Device Identification object IDs are 0-255 (0x00-0xFF)"));
    } else if (nextObjectId != 0) {
        b.addError(QStringLiteral("nextObjectId"),
                   QStringLiteral("next object ID %1 is not allowed: when no more objects follow, Read Device "
                                  "Identification sets it to 0x00")
                       .arg(nextObjectId));
    }
    if (readDeviceIdCode == 4 && objects.size() != 1) {
        b.addError(QStringLiteral("objects"),
                   QStringLiteral("%1 objects is not allowed: an individual access (read device ID code 4) returns "
                                  "exactly one object")
                       .arg(objects.size()));
    }
    qint64 objectBytes = 0;
    for (qsizetype i = 0; i < objects.size(); ++i) {
        b.checkRange(QStringLiteral("objects[%1].id").arg(i), QStringLiteral("object ID"), objects[i].id, 0, 0xFF,
                     QStringLiteral("Read Device Identification object IDs are 0-255 (0x00-0xFF)"));
        b.checkRange(QStringLiteral("objects[%1].value").arg(i), QStringLiteral("object length"),
                     objects[i].value.size(), 0, 0xFF,
                     QStringLiteral("an object's length is one byte, 0-255"));
        objectBytes += 2 + objects[i].value.size();
    }
    if (b.hasErrors())
        return b.finish();
    // MEI type, code, conformity, more follows, next object id, number of objects: 6 bytes.
    if (!b.checkFits(QStringLiteral("objects"), QStringLiteral("the object list"), objectBytes, 6))
        return b.finish();
    b.appendU8(0x0E);
    b.appendU8(readDeviceIdCode);
    b.appendU8(conformityLevel);
    b.appendU8(moreFollows ? 0xFF : 0x00);
    b.appendU8(nextObjectId);
    b.appendU8(int(objects.size()));
    for (const DeviceIdObject &object : objects) {
        b.appendU8(object.id);
        b.appendU8(int(object.value.size()));
        b.appendBytes(object.value);
    }
    return b.finish();
}

BuildResult ResponseBuilder::canopenGeneralReference(const QByteArray &data)
{
    return encapsulatedInterface(0x0D, data);
}

BuildResult ResponseBuilder::encapsulatedInterface(int meiType, const QByteArray &data)
{
    return RequestBuilder::encapsulatedInterface(meiType, data);
}

BuildResult ResponseBuilder::userDefined(int functionCode, const QByteArray &data)
{
    return RequestBuilder::userDefined(functionCode, data);
}

BuildResult ResponseBuilder::exception(int functionCode, int exceptionCode)
{
    const bool validFunction = functionCode >= 1 && functionCode <= 0x7F;
    PduBuilder b{quint8(validFunction ? functionCode | 0x80 : 0x80)};
    // V1.1b3, 7: the exception response is the function code with its high bit set, then the
    // exception code.
    if (!validFunction) {
        b.addError(QStringLiteral("functionCode"),
                   functionCode >= 0x81 && functionCode <= 0xFF
                       ? QStringLiteral("function code %1 already has the exception bit set: pass the function "
                                        "code in error, 1-127 (0x01-0x7F)")
                             .arg(PduBuilder::hex(functionCode, 2))
                       : QStringLiteral("function code %1 is out of range: an exception answers function codes "
                                        "1-127 (0x01-0x7F)")
                             .arg(functionCode));
    }
    b.checkRange(QStringLiteral("exceptionCode"), QStringLiteral("exception code"), exceptionCode, 0, 0xFF,
                 QStringLiteral("an exception code is one byte, 0-255 (0x00-0xFF)"));
    b.appendU8(exceptionCode);
    return b.finish();
}

BuildResult ResponseBuilder::raw(int functionCode, const QByteArray &data)
{
    return RequestBuilder::raw(functionCode, data);
}

} // namespace mbscope
