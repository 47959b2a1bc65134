#include "sim/simulatorhost.h"

#include "sim/faultinjector.h"
#include "sim/generatordriver.h"
#include "sim/profileapplier.h"
#include "sim/simendpoint.h"
#include "sim/simfaultplanrecorder.h"
#include "sim/simscriptdriver.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QMetaObject>
#include <QtCore/QTimer>

#include <algorithm>

namespace mbscope {

namespace {

QString translated(const char *text)
{
    return QCoreApplication::translate("mbscope::SimulatorHost", text);
}

} // namespace

SimulatorHost::SimulatorHost(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<SimValueUpdate>();
    qRegisterMetaType<QList<SimValueUpdate>>();
    qRegisterMetaType<SimTrafficRecord>();
    qRegisterMetaType<QList<SimTrafficRecord>>();
    m_thread.setObjectName(QStringLiteral("mbscope simulator"));
}

SimulatorHost::~SimulatorHost()
{
    blockSignals(true); // whoever listened may be half destroyed already
    stop();
}

bool SimulatorHost::load(const DeviceProfile &profile, QString *error)
{
    if (m_simulator) {
        if (error)
            *error = translated("The simulator is already loaded: start another one for another profile.");
        return false;
    }
    QString why;
    const QList<SimUnit *> units = ProfileApplier::createUnits(profile, nullptr, &why);
    if (units.isEmpty()) {
        if (error)
            *error = translated("The profile '%1' has no usable unit: %2").arg(profile.name, why);
        return false;
    }
    m_anchor = new QObject;
    m_simulator = new Simulator;
    m_driver = new GeneratorDriver;
    m_injector = std::make_unique<FaultInjector>();
    QList<SimUnit *> adopted;
    for (SimUnit *unit : units) {
        if (SimUnit *kept = m_simulator->adoptUnit(std::unique_ptr<SimUnit>(unit))) {
            adopted.append(kept);
            m_unitIds.append(kept->id());
            watch(kept);
        }
    }
    ProfileApplier::configure(m_injector.get(), profile);
    m_simulator->setLimits(profile.limits);
    m_simulator->setLineTable(profile.delimited);
    m_driver->attach(profile, adopted);
    // The engines are made in the simulator's thread (start()); the hosts are set now, so that
    // a delimited endpoint served by a script alone can listen.
    m_scripts = new SimScriptDriver;
    m_scripts->attach(profile, m_simulator, nullptr, false);
    m_scriptNames = m_scripts->describe();
    connect(m_scripts, &SimScriptDriver::logged, this, &SimulatorHost::scriptLogged);
    auto *recorder = new SimFaultPlanRecorder(m_simulator, m_injector.get(), m_anchor);
    connect(recorder, &SimFaultPlanRecorder::recorded, m_anchor,
            [this](const SimTrafficRecord &record) { noteRecord(record); }, Qt::DirectConnection);
    m_profile = profile;
    return true;
}

void SimulatorHost::watch(SimUnit *unit)
{
    const quint8 id = unit->id();
    connect(unit, &SimUnit::valuesChanged, m_anchor,
            [this, id](SimTable table, int start, int count) { noteChanged(id, table, start, count); },
            Qt::DirectConnection);
}

std::optional<LinkUrl> SimulatorHost::listen(const QString &url, QString *error)
{
    const LinkUrl::Result parsed = LinkUrl::parse(url, LinkUse::Listen);
    if (!parsed.url) {
        if (error)
            *error = parsed.error;
        return std::nullopt;
    }
    return listen(*parsed.url, error);
}

std::optional<LinkUrl> SimulatorHost::listen(const LinkUrl &url, QString *error)
{
    if (!m_simulator || m_running) {
        if (error)
            *error = translated("Endpoints are added after loading a profile and before the simulator starts.");
        return std::nullopt;
    }
    SimEndpoint *endpoint = m_simulator->listen(url, ProfileApplier::endpointOptions(m_profile), error);
    if (!endpoint)
        return std::nullopt;
    m_bound.append(endpoint->boundUrl());
    m_framings.insert(endpoint->name(), endpoint->framing());
    return endpoint->boundUrl();
}

void SimulatorHost::start()
{
    if (!m_simulator || m_running)
        return;
    m_running = true;
    auto *timer = new QTimer(m_anchor);
    timer->setInterval(m_reportIntervalMs);
    connect(timer, &QTimer::timeout, m_anchor, [this] { report(); });
    m_thread.start();
    m_simulator->moveToThread(&m_thread);
    m_driver->moveToThread(&m_thread);
    m_scripts->moveToThread(&m_thread);
    m_anchor->moveToThread(&m_thread);
    for (quint8 id : std::as_const(m_unitIds))
        m_simulator->unit(id)->moveToThread(&m_thread); // held by the simulator, not its QObject children
    // Timers start in the thread that runs them.
    GeneratorDriver *driver = m_driver;
    SimScriptDriver *scripts = m_scripts;
    QMetaObject::invokeMethod(m_anchor, [driver, scripts, timer] {
        scripts->load();
        scripts->start();
        driver->start();
        timer->start();
    }, Qt::QueuedConnection);
}

void SimulatorHost::stop()
{
    if (!m_simulator)
        return;
    Simulator *simulator = m_simulator;
    GeneratorDriver *driver = m_driver;
    SimScriptDriver *scripts = m_scripts;
    QObject *anchor = m_anchor;
    auto teardown = [simulator, driver, scripts, anchor] {
        driver->stop();
        delete driver;
        delete scripts; // takes the scripts off the simulator first
        const QObjectList children = anchor->children();
        qDeleteAll(children); // the recorder detaches the fault hook, the timer stops
        simulator->closeAll();
        delete simulator;
    };
    if (m_running) {
        // Sockets and timers are deleted in the thread they belong to, then the thread ends.
        QMetaObject::invokeMethod(m_anchor, teardown, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    } else {
        teardown();
    }
    delete m_anchor;
    m_anchor = nullptr;
    m_simulator = nullptr;
    m_driver = nullptr;
    m_scripts = nullptr;
    m_injector.reset();
    const bool wasRunning = m_running;
    m_running = false;
    if (wasRunning)
        Q_EMIT stopped();
}

QList<SimValueUpdate> SimulatorHost::snapshot(quint8 unit) const
{
    if (!m_simulator)
        return {};
    if (!m_running)
        return read(unit);
    QList<SimValueUpdate> out;
    QMetaObject::invokeMethod(m_anchor, [this, unit, &out] { out = read(unit); }, Qt::BlockingQueuedConnection);
    return out;
}

QList<SimValueUpdate> SimulatorHost::read(quint8 unitId) const
{
    QList<SimValueUpdate> out;
    const SimUnit *unit = m_simulator->unit(unitId);
    if (!unit)
        return out;
    for (int t = 0; t < SimTableCount; ++t) {
        const auto table = SimTable(t);
        for (const SimRange &range : unit->ranges(table))
            out.append(SimValueUpdate{unitId, table, range.start, range.values});
    }
    return out;
}

void SimulatorHost::setValue(quint8 unit, SimTable table, int address, quint16 value)
{
    if (!m_simulator)
        return;
    Simulator *simulator = m_simulator;
    auto apply = [simulator, unit, table, address, value] {
        if (SimUnit *target = simulator->unit(unit))
            target->setValue(table, address, value);
    };
    if (m_running)
        QMetaObject::invokeMethod(m_anchor, apply, Qt::QueuedConnection);
    else
        apply();
}

void SimulatorHost::reloadScripts()
{
    if (!m_scripts)
        return;
    SimScriptDriver *scripts = m_scripts;
    if (m_running)
        QMetaObject::invokeMethod(m_anchor, [scripts] { scripts->reload(); }, Qt::QueuedConnection);
}

FaultRuleSet SimulatorHost::faultRules() const
{
    return m_injector ? m_injector->rules() : FaultRuleSet{};
}

void SimulatorHost::setFaultRules(const FaultRuleSet &rules)
{
    if (m_injector)
        m_injector->setRules(rules);
}

void SimulatorHost::noteChanged(quint8 unit, SimTable table, int start, int count)
{
    m_dirty.append({DirtyKey{unit, table}, {start, start + count}});
}

void SimulatorHost::noteRecord(const SimTrafficRecord &record)
{
    m_pending.append(record);
    m_pending.last().framing = m_framings.value(record.entry.endpoint, Framing::Tcp);
    if (m_pending.size() > m_backlogLimit) {
        const qsizetype excess = m_pending.size() - m_backlogLimit;
        m_pending.remove(0, excess);
        m_lost += int(excess);
    }
}

void SimulatorHost::report()
{
    if (!m_dirty.isEmpty()) {
        // Merge the spans that overlap or touch, per unit and table, and read them once: a
        // generator ticking many times between two reports costs one update.
        std::sort(m_dirty.begin(), m_dirty.end());
        QList<SimValueUpdate> updates;
        qsizetype i = 0;
        while (i < m_dirty.size()) {
            const DirtyKey key = m_dirty[i].first;
            int start = m_dirty[i].second.first;
            int end = m_dirty[i].second.second;
            ++i;
            while (i < m_dirty.size() && m_dirty[i].first == key && m_dirty[i].second.first <= end) {
                end = std::max(end, m_dirty[i].second.second);
                ++i;
            }
            if (const SimUnit *unit = m_simulator->unit(key.first)) {
                const QList<quint16> values = unit->values(key.second, start, end - start);
                if (!values.isEmpty())
                    updates.append(SimValueUpdate{key.first, key.second, quint16(start), values});
            }
        }
        m_dirty.clear();
        if (!updates.isEmpty())
            Q_EMIT valuesUpdated(updates);
    }
    if (!m_pending.isEmpty() || m_lost > 0) {
        const int lost = std::exchange(m_lost, 0);
        Q_EMIT trafficRecorded(std::exchange(m_pending, {}), lost);
    }
}

} // namespace mbscope

#include "moc_simulatorhost.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
