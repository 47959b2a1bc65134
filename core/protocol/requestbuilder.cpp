// Request builders for the data access functions (V1.1b3, 6.1-6.6, 6.11, 6.12, 6.14-6.18).
// The diagnostics, encapsulated interface and raw builders are in requestbuilderdiagnostics.cpp.
#include "requestbuilder.h"
#include "quantitylimits.h"

#include "pdubuilder.h"

namespace mbscope {

namespace {

// V1.1b3, 6.14/6.15: a file holds 10000 records, numbered 0-9999 (0x0000-0x270F).
constexpr int RecordsPerFile = 10000;

// Start address and quantity of a write of values (0F, 10: V1.1b3 6.11, 6.12), checked and, when
// all is well, appended; the span is checked only for a quantity within its limits.
bool writeHeader(PduBuilder &b, int startAddress, qint64 quantity, int maxQuantity, const char *unit)
{
    b.checkAddress(QStringLiteral("startAddress"), QStringLiteral("start address"), startAddress);
    if (b.checkQuantity(QStringLiteral("values"), QStringLiteral("quantity"), quantity, maxQuantity, "writes", unit))
        b.checkSpan(QStringLiteral("values"), QStringLiteral("start address"), startAddress, quantity);
    if (b.hasErrors())
        return false;
    b.appendU16(startAddress);
    b.appendU16(int(quantity));
    return true;
}

QString indexed(const char *list, qsizetype index, const char *member)
{
    return QStringLiteral("%1[%2].%3").arg(QLatin1String(list)).arg(index).arg(QLatin1String(member));
}

// The checks that Read and Write File Record share for one sub-request (V1.1b3, 6.14/6.15).
void checkFileRecord(PduBuilder &b, qsizetype index, int referenceType, int fileNumber, int recordNumber,
                     qint64 recordLength, int maxLength, const char *verb, const char *lengthMember)
{
    const QString function = QString::fromLatin1(b.functionName());
    b.checkRange(indexed("subRequests", index, "referenceType"), QStringLiteral("reference type"), referenceType, 6, 6,
                 QStringLiteral("%1 requires reference type 6").arg(function));
    b.checkRange(indexed("subRequests", index, "fileNumber"), QStringLiteral("file number"), fileNumber, 1, 0xFFFF,
                 QStringLiteral("%1 addresses files 1-65535 (0x0001-0xFFFF)").arg(function));
    b.checkRange(indexed("subRequests", index, "recordNumber"), QStringLiteral("record number"), recordNumber, 0,
                 RecordsPerFile - 1, QStringLiteral("%1 addresses records 0-9999 (0x0000-0x270F)").arg(function));
    const QString lengthParameter = indexed("subRequests", index, lengthMember);
    const bool lengthOk = b.checkRange(lengthParameter, QStringLiteral("record length"), recordLength, 1, maxLength,
                                       QStringLiteral("%1 %2 1-%3 registers per sub-request")
                                           .arg(function, QLatin1String(verb))
                                           .arg(maxLength));
    if (lengthOk && recordNumber >= 0 && recordNumber < RecordsPerFile && recordNumber + recordLength > RecordsPerFile) {
        b.addError(lengthParameter,
                   QStringLiteral("record number %1 with record length %2 ends at record %3, past the last record "
                                  "9999 of a file: %4 addresses records 0-9999")
                       .arg(recordNumber)
                       .arg(recordLength)
                       .arg(recordNumber + recordLength - 1)
                       .arg(function));
    }
}

} // namespace

BuildResult RequestBuilder::readCoils(int startAddress, int quantity)
{
    return PduBuilder::startAndQuantity(0x01, startAddress, quantity, QuantityLimits::kReadBits, "reads", "coils");
}

BuildResult RequestBuilder::readDiscreteInputs(int startAddress, int quantity)
{
    return PduBuilder::startAndQuantity(0x02, startAddress, quantity, QuantityLimits::kReadBits, "reads", "discrete inputs");
}

BuildResult RequestBuilder::readHoldingRegisters(int startAddress, int quantity)
{
    return PduBuilder::startAndQuantity(0x03, startAddress, quantity, QuantityLimits::kReadRegisters, "reads", "registers");
}

BuildResult RequestBuilder::readInputRegisters(int startAddress, int quantity)
{
    return PduBuilder::startAndQuantity(0x04, startAddress, quantity, QuantityLimits::kReadRegisters, "reads", "registers");
}

BuildResult RequestBuilder::writeSingleCoil(int address, bool on)
{
    return writeSingleCoilValue(address, on ? 0xFF00 : 0x0000);
}

BuildResult RequestBuilder::writeSingleCoilValue(int address, int value)
{
    PduBuilder b(0x05);
    b.checkAddress(QStringLiteral("address"), QStringLiteral("address"), address);
    // V1.1b3, 6.5: "All other values are illegal and will not affect the output."
    if (value != 0xFF00 && value != 0x0000) {
        b.addError(QStringLiteral("value"),
                   QStringLiteral("value %1 (%2) is not a coil value: Write Single Coil accepts only 0xFF00 (ON) or "
                                  "0x0000 (OFF)")
                       .arg(value)
                       .arg(PduBuilder::hex(value, 4)));
    }
    b.appendU16(address);
    b.appendU16(value);
    return b.finish();
}

BuildResult RequestBuilder::writeSingleRegister(int address, int value)
{
    PduBuilder b(0x06);
    b.checkAddress(QStringLiteral("address"), QStringLiteral("address"), address);
    b.checkU16(QStringLiteral("value"), QStringLiteral("value"), value);
    b.appendU16(address);
    b.appendU16(value);
    return b.finish();
}

BuildResult RequestBuilder::writeMultipleCoils(int startAddress, const QList<bool> &values)
{
    PduBuilder b(0x0F);
    if (writeHeader(b, startAddress, values.size(), QuantityLimits::kWriteCoils, "coils"))
        b.appendBits(values);
    return b.finish();
}

BuildResult RequestBuilder::writeMultipleRegisters(int startAddress, const QList<quint16> &values)
{
    PduBuilder b(0x10);
    if (writeHeader(b, startAddress, values.size(), QuantityLimits::kWriteRegisters, "registers"))
        b.appendRegisters(values);
    return b.finish();
}

BuildResult RequestBuilder::maskWriteRegister(int address, int andMask, int orMask)
{
    PduBuilder b(0x16);
    b.checkAddress(QStringLiteral("address"), QStringLiteral("address"), address);
    b.checkU16(QStringLiteral("andMask"), QStringLiteral("AND mask"), andMask);
    b.checkU16(QStringLiteral("orMask"), QStringLiteral("OR mask"), orMask);
    b.appendU16(address);
    b.appendU16(andMask);
    b.appendU16(orMask);
    return b.finish();
}

BuildResult RequestBuilder::readWriteMultipleRegisters(int readStartAddress, int readQuantity, int writeStartAddress,
                                                       const QList<quint16> &writeValues)
{
    PduBuilder b(0x17);
    const qint64 writeQuantity = writeValues.size();
    b.checkAddress(QStringLiteral("readStartAddress"), QStringLiteral("read start address"), readStartAddress);
    b.checkQuantity(QStringLiteral("readQuantity"), QStringLiteral("read quantity"), readQuantity, QuantityLimits::kReadRegisters, "reads",
                    "registers");
    b.checkSpan(QStringLiteral("readQuantity"), QStringLiteral("read start address"), readStartAddress, readQuantity);
    b.checkAddress(QStringLiteral("writeStartAddress"), QStringLiteral("write start address"), writeStartAddress);
    if (b.checkQuantity(QStringLiteral("writeValues"), QStringLiteral("write quantity"), writeQuantity, QuantityLimits::kReadWriteWrite, "writes",
                        "registers")) {
        b.checkSpan(QStringLiteral("writeValues"), QStringLiteral("write start address"), writeStartAddress,
                    writeQuantity);
    }
    if (b.hasErrors())
        return b.finish();
    b.appendU16(readStartAddress);
    b.appendU16(readQuantity);
    b.appendU16(writeStartAddress);
    b.appendU16(int(writeQuantity));
    b.appendRegisters(writeValues);
    return b.finish();
}

BuildResult RequestBuilder::readFifoQueue(int fifoAddress)
{
    PduBuilder b(0x18);
    b.checkAddress(QStringLiteral("fifoAddress"), QStringLiteral("FIFO pointer address"), fifoAddress);
    b.appendU16(fifoAddress);
    return b.finish();
}

BuildResult RequestBuilder::readFileRecord(const QList<FileRecordRead> &subRequests)
{
    PduBuilder b(0x14);
    // V1.1b3, 6.14: byte count 0x07-0xF5, 7 bytes per sub-request, so 1-35 sub-requests; and the
    // response (2 bytes, then 2 + 2 x length per sub-request) must also fit in 253 bytes.
    const qint64 count = subRequests.size();
    if (count == 0) {
        b.addError(QStringLiteral("subRequests"),
                   QStringLiteral("no sub-requests: Read File Record needs 1-35 (byte count 7-245, 0x07-0xF5)"));
    } else if (count > 35) {
        b.addError(QStringLiteral("subRequests"),
                   QStringLiteral("%1 sub-requests need a byte count of %2: Read File Record allows 7-245 (0x07-0xF5), "
                                  "that is 1-35 sub-requests")
                       .arg(count)
                       .arg(count * 7));
    }
    // A single sub-request can read at most (253 - 2 - 2) / 2 = 124 registers.
    constexpr int MaxLength = (PduBuilder::MaxPduSize - 4) / 2;
    qint64 responseSize = 2;
    for (qsizetype i = 0; i < subRequests.size(); ++i) {
        const FileRecordRead &s = subRequests[i];
        checkFileRecord(b, i, s.referenceType, s.fileNumber, s.recordNumber, s.recordLength, MaxLength, "reads", "recordLength");
        responseSize += 2 + 2 * qint64(qMax(s.recordLength, 0));
    }
    if (!b.hasErrors() && responseSize > PduBuilder::MaxPduSize) {
        b.addError(QStringLiteral("subRequests"),
                   QStringLiteral("the response would be %1 bytes: Read File Record's response (2 bytes, then 2 bytes "
                                  "plus 2 per register for each sub-request) must fit in a 253-byte PDU")
                       .arg(responseSize));
    }
    if (b.hasErrors())
        return b.finish();
    b.appendU8(int(count * 7));
    for (const FileRecordRead &s : subRequests) {
        b.appendU8(s.referenceType);
        b.appendU16(s.fileNumber);
        b.appendU16(s.recordNumber);
        b.appendU16(s.recordLength);
    }
    return b.finish();
}

BuildResult RequestBuilder::writeFileRecord(const QList<FileRecordWrite> &subRequests)
{
    PduBuilder b(0x15);
    // V1.1b3, 6.15: request data length 0x09-0xFB; each sub-request is 7 bytes plus its data.
    // A single sub-request can write at most (253 - 2 - 7) / 2 = 122 registers.
    constexpr int MaxLength = (PduBuilder::MaxPduSize - 9) / 2;
    if (subRequests.isEmpty()) {
        b.addError(QStringLiteral("subRequests"),
                   QStringLiteral("no sub-requests: Write File Record needs at least one (request data length 9-251, "
                                  "0x09-0xFB)"));
    }
    qint64 dataLength = 0;
    for (qsizetype i = 0; i < subRequests.size(); ++i) {
        const FileRecordWrite &s = subRequests[i];
        checkFileRecord(b, i, s.referenceType, s.fileNumber, s.recordNumber, s.values.size(), MaxLength, "writes", "values");
        dataLength += 7 + 2 * qint64(s.values.size());
    }
    if (!b.hasErrors() && dataLength > PduBuilder::MaxDataSize - 1) {
        b.addError(QStringLiteral("subRequests"),
                   QStringLiteral("request data length %1 is out of range: Write File Record allows 9-251 (0x09-0xFB) "
                                  "bytes, the room left in a 253-byte PDU")
                       .arg(dataLength));
    }
    if (b.hasErrors())
        return b.finish();
    b.appendU8(int(dataLength));
    for (const FileRecordWrite &s : subRequests) {
        b.appendU8(s.referenceType);
        b.appendU16(s.fileNumber);
        b.appendU16(s.recordNumber);
        b.appendU16(int(s.values.size()));
        for (quint16 value : s.values)
            b.appendU16(value);
    }
    return b.finish();
}

} // namespace mbscope
