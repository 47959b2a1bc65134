#pragma once

// The shipped rosrao-gamma profile served in-process on rtu-tcp://127.0.0.1:PORT (a port the OS
// chooses), with its value generators running: the device the session tests run plans against.
// The profile is read from the source tree (core tests do not link the compiled-in resources).

#include "profile/deviceprofile.h"
#include "sim/generatordriver.h"
#include "sim/profileapplier.h"
#include "profile/profileloader.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "sim/simunit.h"
#include "transport/linkurl.h"

#include <QtTest/QtTest>

namespace mbscope::sessiontest {

inline QString sourceDir()
{
    return QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../..");
}

class RosraoSim
{
public:
    // False with *error when the profile or the port cannot be had.
    bool start(QString *error)
    {
        const ProfileLoadResult loaded = ProfileLoader::loadFile(sourceDir() + QStringLiteral("/resources/profiles/rosrao-gamma.json"));
        if (!loaded.ok) {
            *error = loaded.errorText();
            return false;
        }
        QList<SimUnit *> units;
        for (const UnitProfile &unit : loaded.profile.units) {
            SimUnit *u = m_sim.addUnit(quint8(unit.id));
            if (!u || !ProfileApplier::apply(unit, u, error))
                return false;
            units.append(u);
        }
        m_driver.attach(loaded.profile, units);
        m_driver.start();
        SimEndpoint *endpoint = m_sim.listen(QStringLiteral("rtu-tcp://127.0.0.1:0"), {}, error);
        if (!endpoint)
            return false;
        m_url = endpoint->boundUrl();
        return true;
    }
    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] Simulator &simulator() { return m_sim; }

private:
    Simulator m_sim;
    GeneratorDriver m_driver;
    LinkUrl m_url;
};

} // namespace mbscope::sessiontest
