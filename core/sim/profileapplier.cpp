#include "sim/profileapplier.h"

#include "sim/faultinjector.h"
#include "sim/simunit.h"

#include <cmath>

namespace mbscope {

bool ProfileApplier::apply(const UnitProfile &profile, SimUnit *unit, QString *error)
{
    unit->setName(profile.name);
    unit->setSupportedFunctions(profile.functions.isEmpty() ? SimUnit::implementedFunctions() : profile.functions);
    unit->setExceptionStatus(profile.exceptionStatus);
    unit->setResponseDelayNs(qint64(std::llround(profile.responseDelay.nominalMs() * 1e6)));

    for (SimTable table : {SimTable::Coils, SimTable::DiscreteInputs, SimTable::InputRegisters,
                           SimTable::HoldingRegisters}) {
        unit->clearRanges(table);
        unit->setSharedTable(table, profile.sharedTables.value(table, table));
    }
    unit->setGapReadsZeros(profile.gapReadsZeros);
    for (const TableEntry &entry : profile.entries) {
        SimRange range;
        range.table = entry.table;
        range.start = entry.address;
        range.count = entry.count;
        range.writable = entry.writable;
        range.name = entry.name;
        range.values = entry.initial;
        QString why;
        if (!unit->addRange(range, &why)) {
            if (error)
                *error = QStringLiteral("unit %1, %2 %3: %4").arg(profile.id).arg(QLatin1String(simTableName(entry.table)))
                             .arg(entry.address).arg(why);
            return false;
        }
    }

    // SimUnit lists no FIFO addresses, so FIFOs that the profile does not name are left alone.
    for (const FifoSpec &fifo : profile.fifos)
        unit->setFifo(fifo.address, fifo.values);
    for (quint16 number : unit->fileNumbers())
        unit->removeFile(number);
    for (const FileSpec &file : profile.files)
        unit->setFile(file.number, file.records, file.writable);

    for (quint8 id : unit->deviceIdObjects().keys())
        unit->removeDeviceIdObject(id);
    for (auto it = profile.deviceId.cbegin(); it != profile.deviceId.cend(); ++it)
        unit->setDeviceIdObject(it.key(), it.value());
    unit->setConformityLevel(profile.conformityLevel);

    const ServerIdSpec serverId = profile.serverId.value_or(ServerIdSpec{});
    unit->setServerId(serverId.id);
    unit->setRunIndicator(serverId.running);
    unit->setAdditionalData(serverId.additionalData);
    return true;
}

QList<SimUnit *> ProfileApplier::createUnits(const DeviceProfile &profile, QObject *parent, QString *error)
{
    QList<SimUnit *> units;
    for (const UnitProfile &u : profile.units) {
        auto *unit = new SimUnit(u.id, parent);
        if (!apply(u, unit, error)) {
            qDeleteAll(units);
            delete unit;
            return {};
        }
        units.append(unit);
    }
    return units;
}

void ProfileApplier::configure(FaultInjector *injector, const DeviceProfile &profile)
{
    injector->clearResponseDelays();
    for (const UnitProfile &u : profile.units)
        injector->setResponseDelay(u.id, u.responseDelay);
    injector->setRules(profile.faults);
}

SimEndpointOptions ProfileApplier::endpointOptions(const DeviceProfile &profile)
{
    SimEndpointOptions options;
    using U = DeviceLimits::UnknownUnit;
    switch (profile.limits.unknownUnit) {
    case U::Auto: options.unknownUnit = SimEndpointOptions::UnknownUnit::Auto; break;
    case U::FirstUnit: options.unknownUnit = SimEndpointOptions::UnknownUnit::FirstUnit; break;
    case U::Exception: options.unknownUnit = SimEndpointOptions::UnknownUnit::Exception; break;
    case U::Silent: options.unknownUnit = SimEndpointOptions::UnknownUnit::Ignore; break;
    }
    if (profile.limits.maxClients > 0)
        options.maxConnections = profile.limits.maxClients;
    options.dropOldestConnection = profile.limits.extraClients == DeviceLimits::ExtraClient::DropOldest;
    options.answerBroadcasts = profile.limits.answersBroadcasts;
    return options;
}

} // namespace mbscope
