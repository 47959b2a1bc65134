#include "sim/simendpoint.h"

#include "transport/monotonicclock.h"

namespace mbscope {

SimEndpoint::SimEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options)
    : m_simulator(simulator)
    , m_url(url)
    , m_boundUrl(url)
    , m_name(url.toString())
    , m_options(options)
{
}

SimEndpoint::~SimEndpoint() = default;

void SimEndpoint::setBound(const LinkUrl &bound, bool listening)
{
    m_boundUrl = bound;
    m_name = bound.toString();
    if (listening && !m_listening)
        m_startedNs = monotonicNowNs();
    m_listening = listening;
}

} // namespace mbscope

#include "moc_simendpoint.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
