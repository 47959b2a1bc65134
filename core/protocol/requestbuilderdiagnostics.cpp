// Request builders for the serial line diagnostics (V1.1b3, 6.7-6.10, 6.13), the encapsulated
// interface (6.19-6.21), user-defined codes (5.1) and raw PDUs.
#include "requestbuilder.h"

#include "diagnosticrules.h"
#include "pdubuilder.h"

namespace mbscope {

namespace {

BuildResult bare(quint8 function)
{
    PduBuilder b(function);
    return b.finish();
}

BuildResult withData(PduBuilder &b, const QByteArray &data)
{
    b.checkFits(QStringLiteral("data"), QStringLiteral("data"), data.size());
    if (!b.hasErrors())
        b.appendBytes(data);
    return b.finish();
}

} // namespace

BuildResult RequestBuilder::readExceptionStatus()
{
    return bare(0x07);
}

BuildResult RequestBuilder::getCommEventCounter()
{
    return bare(0x0B);
}

BuildResult RequestBuilder::getCommEventLog()
{
    return bare(0x0C);
}

BuildResult RequestBuilder::reportServerId()
{
    return bare(0x11);
}

BuildResult RequestBuilder::diagnostics(int subFunction, const QByteArray &data)
{
    return diagnosticrules::build(subFunction, data, Direction::Request);
}

BuildResult RequestBuilder::diagnostics(int subFunction)
{
    return diagnostics(subFunction, QByteArray(2, '\0'));
}

BuildResult RequestBuilder::restartCommunications(bool clearEventLog)
{
    return diagnostics(0x01, clearEventLog ? QByteArray::fromHex("FF00") : QByteArray(2, '\0'));
}

BuildResult RequestBuilder::changeAsciiInputDelimiter(int character)
{
    PduBuilder b(0x08);
    if (!b.checkRange(QStringLiteral("character"), QStringLiteral("delimiter character"), character, 0, 0xFF,
                      QStringLiteral("Change ASCII Input Delimiter takes one byte, 0-255 (0x00-0xFF)"))) {
        return b.finish();
    }
    QByteArray data(2, '\0');
    data[0] = char(quint8(character));
    return diagnostics(0x03, data);
}

BuildResult RequestBuilder::readDeviceIdentification(int readDeviceIdCode, int objectId)
{
    PduBuilder b(0x2B);
    // V1.1b3, 6.21: Read Device ID code 01-04; Object Id 0x00-0xFF.
    b.checkRange(QStringLiteral("readDeviceIdCode"), QStringLiteral("read device ID code"), readDeviceIdCode, 1, 4,
                 QStringLiteral("Read Device Identification takes 1-4 (1 basic, 2 regular, 3 extended stream access, "
                                "4 one specific object)"));
    b.checkRange(QStringLiteral("objectId"), QStringLiteral("object ID"), objectId, 0, 0xFF,
                 QStringLiteral("Read Device Identification object IDs are 0-255 (0x00-0xFF)"));
    b.appendU8(0x0E);
    b.appendU8(readDeviceIdCode);
    b.appendU8(objectId);
    return b.finish();
}

BuildResult RequestBuilder::canopenGeneralReference(const QByteArray &data)
{
    // V1.1b3, 6.20: MEI type 13 is licensed to CiA; its data is not defined by the Modbus
    // specification, only the 253-byte PDU limit applies.
    return encapsulatedInterface(0x0D, data);
}

BuildResult RequestBuilder::encapsulatedInterface(int meiType, const QByteArray &data)
{
    PduBuilder b(0x2B);
    b.checkU8(QStringLiteral("meiType"), QStringLiteral("MEI type"), meiType);
    b.appendU8(meiType);
    return withData(b, data);
}

BuildResult RequestBuilder::userDefined(int functionCode, const QByteArray &data)
{
    const bool userDefinedCode = (functionCode >= 65 && functionCode <= 72) || (functionCode >= 100 && functionCode <= 110);
    PduBuilder b{quint8(userDefinedCode ? functionCode : 0)};
    if (!userDefinedCode) {
        b.addError(QStringLiteral("functionCode"),
                   QStringLiteral("function code %1 is not user-defined: user-defined function codes are 65-72 "
                                  "(0x41-0x48) and 100-110 (0x64-0x6E) (V1.1b3, 5.1)")
                       .arg(functionCode));
        return b.finish();
    }
    return withData(b, data);
}

BuildResult RequestBuilder::raw(int functionCode, const QByteArray &data)
{
    PduBuilder b{quint8(functionCode)};
    if (!b.checkRange(QStringLiteral("functionCode"), QStringLiteral("function code"), functionCode, 0, 0xFF,
                      QStringLiteral("a function code is one byte, 0-255 (0x00-0xFF)"))) {
        return b.finish();
    }
    return withData(b, data);
}

} // namespace mbscope
