#include "embeddedsimulator.h"

#include "sim/faultinjector.h"
#include "sim/generatordriver.h"
#include "sim/profileapplier.h"
#include "sim/profileloader.h"
#include "sim/simendpoint.h"
#include "sim/simexchange.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtCore/QMetaObject>

namespace mbscope {

EmbeddedSimulator::EmbeddedSimulator(QObject *parent)
    : QObject(parent)
{
    m_thread.setObjectName(QStringLiteral("mbscope simulator"));
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

    auto simulator = std::make_unique<Simulator>();
    auto driver = std::make_unique<GeneratorDriver>();
    auto injector = std::make_unique<FaultInjector>();
    QString error;
    const QList<SimUnit *> units = ProfileApplier::createUnits(loaded.profile, nullptr, &error);
    if (units.isEmpty()) {
        m_started.error = tr("The simulator's profile '%1' has no usable unit: %2").arg(profile, error);
        return m_started;
    }
    QList<SimUnit *> adopted;
    for (SimUnit *unit : units) {
        if (SimUnit *kept = simulator->adoptUnit(std::unique_ptr<SimUnit>(unit)))
            adopted.append(kept);
    }
    ProfileApplier::configure(injector.get(), loaded.profile);
    driver->attach(loaded.profile, adopted);
    // The injector draws each answer's response delay from the profile (and applies its fault
    // rules); it is called in the simulator's thread and serialises itself.
    FaultInjector *rawInjector = injector.get();
    simulator->setFaultHook([rawInjector](const SimExchange &exchange) {
        return rawInjector->plan(FaultContext::forRequest(exchange.framing, exchange.requestAdu, exchange.responseAdu,
                                                          exchange.responseDelayNs));
    });

    SimEndpoint *endpoint = simulator->listen(url, {}, &error);
    if (!endpoint) {
        // Taken port (or a port we may not bind): a free loopback port keeps the first run working.
        const LinkUrl::Result asked = LinkUrl::parse(url, LinkUse::Listen);
        if (asked.url) {
            LinkUrl anyPort = *asked.url;
            anyPort.port = 0;
            QString secondError;
            endpoint = simulator->listen(anyPort, {}, &secondError);
            if (endpoint)
                m_started.note = tr("Port %1 is in use by another program, so the simulator listens on port %2 instead.")
                                     .arg(asked.url->port)
                                     .arg(endpoint->boundUrl().port);
        }
    }
    if (!endpoint) {
        m_started.error = tr("The simulator cannot listen on %1: %2").arg(url, error);
        return m_started;
    }
    m_started.ok = true;
    m_started.url = endpoint->boundUrl();
    m_loaded = loaded.profile;

    m_injector = std::move(injector);
    m_simulator = simulator.release();
    m_driver = driver.release();
    m_anchor = new QObject;
    m_thread.start();
    m_simulator->moveToThread(&m_thread);
    m_driver->moveToThread(&m_thread);
    m_anchor->moveToThread(&m_thread);
    for (SimUnit *unit : adopted)
        unit->moveToThread(&m_thread); // held by the simulator, but not its QObject children
    // The generator timers must start in the thread that runs them.
    QMetaObject::invokeMethod(m_driver, &GeneratorDriver::start, Qt::QueuedConnection);
    return m_started;
}

void EmbeddedSimulator::stop()
{
    if (!m_simulator)
        return;
    // Sockets and timers are deleted in the thread they belong to, then the thread ends.
    Simulator *simulator = m_simulator;
    GeneratorDriver *driver = m_driver;
    QMetaObject::invokeMethod(
        m_anchor,
        [simulator, driver] {
            driver->stop();
            delete driver;
            simulator->closeAll();
            delete simulator;
        },
        Qt::BlockingQueuedConnection);
    m_simulator = nullptr;
    m_driver = nullptr;
    m_thread.quit();
    m_thread.wait();
    delete m_anchor;
    m_anchor = nullptr;
    m_injector.reset();
}

} // namespace mbscope
