#pragma once

#include "profile/deviceprofile.h"
#include "profile/faultrule.h"
#include "sim/simtrafficrecord.h"
#include "sim/simvalueupdate.h"
#include "transport/linkurl.h"

#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QThread>

#include <memory>
#include <optional>
#include <utility>

namespace mbscope {

class FaultInjector;
class GeneratorDriver;
class SimFaultPlanRecorder;
class SimScriptDriver;
class SimUnit;
class Simulator;

// A running simulator for a window: a device profile's units, value generators and fault
// injector behind one or more endpoints, on a thread of its own so that answering never waits
// for painting, and a poll measured against it measures the client, not the GUI's backlog.
//
// What views need crosses the thread in batches (at most one of each per report interval):
// valuesUpdated() with every value that changed (by generators, clients or setValue), and
// trafficRecorded() with every request and what the fault plan did to its answer. Fault rules
// can be replaced at any time (the injector serialises itself): the next request sees them.
//
//     SimulatorHost host;
//     host.load(profile, &error);
//     std::optional<LinkUrl> bound = host.listen(QStringLiteral("tcp://127.0.0.1:0"), &error);
//     host.start();
//
// One-shot: after stop() the simulator is gone; start another host to serve again.
class SimulatorHost : public QObject
{
    Q_OBJECT
public:
    explicit SimulatorHost(QObject *parent = nullptr);
    ~SimulatorHost() override;

    // ---- Before start(), in the owner's thread ----
    // The profile's units, generators, response delays and fault rules. False with *error set.
    bool load(const DeviceProfile &profile, QString *error = nullptr);
    // Binds one endpoint; the URL as bound (port 0: the port the OS chose), or nullopt with *error.
    std::optional<LinkUrl> listen(const LinkUrl &url, QString *error = nullptr);
    std::optional<LinkUrl> listen(const QString &url, QString *error = nullptr);
    void setReportIntervalMs(int ms) { m_reportIntervalMs = ms; }

    void start();
    // Closes every endpoint and ends the thread; emits stopped().
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }

    [[nodiscard]] const DeviceProfile &profile() const { return m_profile; }
    [[nodiscard]] QList<LinkUrl> boundUrls() const { return m_bound; }
    [[nodiscard]] QList<quint8> unitIds() const { return m_unitIds; }

    // ---- Any time, from the owner's thread ----
    // Every value of every table of a unit as it is now (waits briefly for the simulator's
    // thread); empty once stopped.
    [[nodiscard]] QList<SimValueUpdate> snapshot(quint8 unit) const;
    // Sets a value in the simulator's thread (no writable check: the panel is the device's
    // front panel); the change comes back through valuesUpdated().
    void setValue(quint8 unit, SimTable table, int address, quint16 value);
    // The units' scripts ("unit 1: meter.js"), loaded in the simulator's thread when it starts.
    [[nodiscard]] QStringList scripts() const { return m_scriptNames; }
    // Loads every script again from its file (a fresh engine each) in the simulator's thread;
    // what happened comes back through scriptLogged().
    void reloadScripts();
    [[nodiscard]] FaultRuleSet faultRules() const;
    void setFaultRules(const FaultRuleSet &rules);
    // Traffic records waiting for the next report are capped at this many; older ones are
    // counted as lost in trafficRecorded().
    void setTrafficBacklog(int records) { m_backlogLimit = records; }

Q_SIGNALS:
    // Emitted from the simulator's thread: queued to receivers in other threads.
    void valuesUpdated(const QList<mbscope::SimValueUpdate> &updates);
    void trafficRecorded(const QList<mbscope::SimTrafficRecord> &records, int lost);
    void stopped();
    // A script's log line or error (who: "unit 1: meter.js"), queued from the simulator's thread.
    void scriptLogged(const QString &who, const QString &text, bool error);

private:
    using DirtyKey = std::pair<quint8, SimTable>;
    void watch(SimUnit *unit);
    void noteChanged(quint8 unit, SimTable table, int start, int count);
    void noteRecord(const SimTrafficRecord &record);
    void report(); // in the simulator's thread
    [[nodiscard]] QList<SimValueUpdate> read(quint8 unit) const;

    QThread m_thread;
    QObject *m_anchor = nullptr; // lives in m_thread: parent of what runs there
    Simulator *m_simulator = nullptr;
    GeneratorDriver *m_driver = nullptr;
    SimScriptDriver *m_scripts = nullptr;
    QStringList m_scriptNames;
    std::unique_ptr<FaultInjector> m_injector;
    DeviceProfile m_profile;
    QList<quint8> m_unitIds;
    QList<LinkUrl> m_bound;
    QHash<QString, Framing> m_framings; // by endpoint name, for the traffic records
    int m_reportIntervalMs = 100;
    int m_backlogLimit = 20000;
    bool m_running = false;
    // In the simulator's thread only:
    QList<std::pair<DirtyKey, std::pair<int, int>>> m_dirty; // (unit, table), [start, end)
    QList<SimTrafficRecord> m_pending;
    int m_lost = 0;
};

} // namespace mbscope
