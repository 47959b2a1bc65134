#pragma once

#include "profile/deviceprofile.h"
#include "sim/simendpointoptions.h"

#include <QtCore/QList>
#include <QtCore/QString>

class QObject;

namespace mbscope {

class FaultInjector;
class SimUnit;

// Puts a loaded device profile into the simulator's objects: SimUnits (name, function codes,
// ranges with initial values, FIFOs, files, identification, server id, nominal response time)
// and a FaultInjector (rules, response delay distributions). Value generators are attached
// separately (GeneratorDriver::attach), since they run with the simulator.
class ProfileApplier
{
public:
    // Configures unit as the profile describes it, replacing its ranges, files and identification
    // objects, and setting the FIFOs the profile names. False with a message when the unit refuses a range (cannot happen
    // with a profile the loader accepted, which checks overlaps and bounds).
    static bool apply(const UnitProfile &profile, SimUnit *unit, QString *error = nullptr);
    // New SimUnits, one per unit of the profile, children of parent. Empty on error.
    [[nodiscard]] static QList<SimUnit *> createUnits(const DeviceProfile &profile, QObject *parent,
                                                      QString *error = nullptr);
    // The profile's fault rules and each unit's response delay distribution.
    static void configure(FaultInjector *injector, const DeviceProfile &profile);
    // What each endpoint serving the profile does with unknown unit ids and extra clients.
    [[nodiscard]] static SimEndpointOptions endpointOptions(const DeviceProfile &profile);
};

} // namespace mbscope
