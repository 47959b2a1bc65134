// Link::create, apart from link.cpp: the factory knows every kind of link, and every kind of link
// knows Link, so keeping them in one file would make the base class and its subclasses depend on
// each other (tests/docs/tst_layers checks there is no such cycle).
#include "link.h"

#include "seriallink.h"
#include "tcplink.h"
#include "tlslink.h"
#include "udplink.h"

namespace mbscope {

Link *Link::create(const LinkUrl &url, QObject *parent)
{
    switch (url.kind) {
    case LinkKind::Tcp:
    case LinkKind::RtuTcp:
    case LinkKind::AsciiTcp: return new TcpLink(url, parent);
    case LinkKind::Udp:
    case LinkKind::RtuUdp: return new UdpLink(url, parent);
    case LinkKind::Rtu:
    case LinkKind::Ascii: return new SerialLink(url, parent);
    case LinkKind::Tls: return new TlsLink(url, parent);
    }
    return new TcpLink(url, parent);
}

} // namespace mbscope
