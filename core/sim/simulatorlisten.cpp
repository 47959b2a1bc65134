// Simulator::listen, apart from simulator.cpp: it makes every kind of endpoint, and every endpoint
// knows the Simulator it hands frames to, so keeping them in one file would make the simulator and
// its endpoints depend on each other (tests/docs/tst_layers checks there is no such cycle).
#include "sim/simulator.h"

#include "sim/simdatagramendpoint.h"
#include "sim/simserialendpoint.h"
#include "sim/simstreamendpoint.h"
#include "transport/linkurl.h"

namespace mbscope {

SimEndpoint *Simulator::listen(const QString &url, const SimEndpointOptions &options, QString *error)
{
    const LinkUrl::Result parsed = LinkUrl::parse(url, LinkUse::Listen);
    if (!parsed.url) {
        if (error)
            *error = parsed.error;
        return nullptr;
    }
    return listen(*parsed.url, options, error);
}

SimEndpoint *Simulator::listen(const LinkUrl &url, const SimEndpointOptions &options, QString *error)
{
    if (url.delimited.enabled && m_lineTable.isEmpty() && !m_lineScript) {
        if (error)
            *error = url.toString() + QStringLiteral(": framing=delimited needs a profile with a 'delimited' table of requests "
                                                     "and answers or a script (docs/profiles.md, \"Delimited protocols\")");
        return nullptr;
    }
    SimEndpoint *endpoint = nullptr;
    switch (url.kind) {
    case LinkKind::Tcp:
    case LinkKind::RtuTcp:
    case LinkKind::AsciiTcp:
    case LinkKind::Tls:
        endpoint = new SimStreamEndpoint(this, url, options);
        break;
    case LinkKind::Udp:
    case LinkKind::RtuUdp:
        endpoint = new SimDatagramEndpoint(this, url, options);
        break;
    case LinkKind::Rtu:
    case LinkKind::Ascii:
        endpoint = new SimSerialEndpoint(this, url, options);
        break;
    }
    QString why;
    if (!endpoint->start(&why)) {
        delete endpoint;
        if (error)
            *error = why;
        return nullptr;
    }
    endpoint->setParent(this);
    m_endpoints.append(endpoint);
    return endpoint;
}

} // namespace mbscope
