#include "broadcastrule.h"

#include "adubuilder.h"
#include "functioncode.h"

namespace mbscope {

bool BroadcastRule::wantsAnswer(quint8 functionCode)
{
    switch (functionCode) {
    case 0x01: case 0x02: case 0x03: case 0x04: // reads of the four tables
    case 0x07: case 0x0B: case 0x0C: case 0x11: // exception status, event counter and log, server id
    case 0x14: case 0x17: case 0x18: case 0x2B: // file record, read/write registers, FIFO, device id
        return true;
    default:
        return false;
    }
}

QString BroadcastRule::readProblem(quint8 functionCode)
{
    return QStringLiteral("%1 to unit 0 can return nothing: a broadcast is never answered, and broadcasts are for writes "
                          "only (MODBUS over Serial Line V1.02, 2.1)")
        .arg(QString::fromLatin1(functionName(functionCode)));
}

bool BroadcastRule::isBroadcastRead(QByteArrayView adu, Framing framing)
{
    return !broadcastReadProblem(adu, framing).isEmpty();
}

QString BroadcastRule::broadcastReadProblem(QByteArrayView adu, Framing framing)
{
    if (framing != Framing::Rtu && framing != Framing::Ascii)
        return {};
    const AduParts parts = AduBuilder::parse(adu, framing);
    if (parts.unitId != 0 || parts.pdu.isEmpty() || !wantsAnswer(quint8(parts.pdu.at(0))))
        return {};
    return readProblem(quint8(parts.pdu.at(0)));
}

} // namespace mbscope
