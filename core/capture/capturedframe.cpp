#include "capturedframe.h"

namespace mbscope {

namespace {

QString endpoint(const IpAddress &address, quint16 port)
{
    return address.v6 ? QStringLiteral("[%1]:%2").arg(address.toString()).arg(port)
                      : QStringLiteral("%1:%2").arg(address.toString()).arg(port);
}

} // namespace

QString CaptureConversation::clientText() const
{
    return isSerial() || !clientKnown ? QString() : endpoint(client, clientPort);
}

QString CaptureConversation::serverText() const
{
    if (isSerial())
        return serialPort;
    return serverKnown ? endpoint(server, serverPort) : serverName;
}

QString CaptureConversation::description() const
{
    if (isSerial())
        return QStringLiteral("serial %1 (Modbus %2)").arg(serialPort, framing == Framing::Ascii ? QStringLiteral("ASCII") : QStringLiteral("RTU"));
    const QString clientEnd = clientKnown ? clientText() : QStringLiteral("(client not recorded)");
    const QString what = framing == Framing::Rtu ? (udp ? QStringLiteral("RTU over UDP") : QStringLiteral("RTU over TCP"))
                                                 : (udp ? QStringLiteral("Modbus UDP") : QStringLiteral("Modbus TCP"));
    return QStringLiteral("%1 %2 -> %3 (%4)")
        .arg(udp ? QStringLiteral("udp") : QStringLiteral("tcp"), clientEnd, serverText(), what);
}

} // namespace mbscope
