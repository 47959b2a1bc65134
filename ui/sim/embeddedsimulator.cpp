#include "embeddedsimulator.h"

#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

namespace mbscope {

EmbeddedSimulator::EmbeddedSimulator(QObject *parent)
    : QObject(parent)
{
}

EmbeddedSimulator::~EmbeddedSimulator()
{
    stop();
}

EmbeddedSimulator::Started EmbeddedSimulator::start(const QString &profile, const QString &url)
{
    stop();
    m_started = {};
    m_profile = profile;
    const ProfileLoadResult loaded = ProfileLoader::load(profile);
    if (!loaded.ok) {
        m_started.error = tr("The simulator's profile '%1' cannot be loaded: %2").arg(profile, loaded.errorText());
        return m_started;
    }

    auto *host = new SimulatorHost(this);
    QString error;
    if (!host->load(loaded.profile, &error)) {
        delete host;
        m_started.error = tr("The simulator's profile '%1' has no usable unit: %2").arg(profile, error);
        return m_started;
    }
    std::optional<LinkUrl> bound = host->listen(url, &error);
    if (!bound) {
        // Taken port (or a port we may not bind): a free loopback port keeps the first run working.
        const LinkUrl::Result asked = LinkUrl::parse(url, LinkUse::Listen);
        if (asked.url) {
            LinkUrl anyPort = *asked.url;
            anyPort.port = 0;
            QString secondError;
            bound = host->listen(anyPort, &secondError);
            if (bound)
                m_started.note = tr("Port %1 is in use by another program, so the simulator listens on port %2 instead.")
                                     .arg(asked.url->port)
                                     .arg(bound->port);
        }
    }
    if (!bound) {
        delete host;
        m_started.error = tr("The simulator cannot listen on %1: %2").arg(url, error);
        return m_started;
    }
    m_started.ok = true;
    m_started.url = *bound;
    m_loaded = loaded.profile;
    host->start();
    m_host = host;
    Q_EMIT hostStarted(host);
    return m_started;
}

void EmbeddedSimulator::stop()
{
    if (m_host) {
        m_host->stop();
        delete m_host.data();
    }
}

bool EmbeddedSimulator::isRunning() const
{
    return m_host && m_host->isRunning();
}

SimulatorHost *EmbeddedSimulator::host() const
{
    return m_host.data();
}

} // namespace mbscope
