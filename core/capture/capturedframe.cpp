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
    return endpoint(client, clientPort);
}

QString CaptureConversation::serverText() const
{
    return endpoint(server, serverPort);
}

QString CaptureConversation::description() const
{
    const QString what = framing == Framing::Rtu ? (udp ? QStringLiteral("RTU over UDP") : QStringLiteral("RTU over TCP"))
                                                 : (udp ? QStringLiteral("Modbus UDP") : QStringLiteral("Modbus TCP"));
    return QStringLiteral("%1 %2 -> %3 (%4)")
        .arg(udp ? QStringLiteral("udp") : QStringLiteral("tcp"), clientText(), serverText(), what);
}

} // namespace mbscope
