#pragma once

#include "profile/deviceprofile.h"
#include "sim/faultinjector.h"
#include "sim/faultplan.h"
#include "sim/generatordriver.h"
#include "sim/simfaultplanrecorder.h"
#include "sim/simscriptdriver.h"
#include "sim/simlogentry.h"
#include "sim/simulator.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QHash>
#include <QtCore/QStringList>
#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QStringList>
#include <QtCore/QTimer>

#include <optional>

class QTextStream;

namespace mbscope {
class TrafficLog;
}

namespace mbscope::app {

// What `mbscope simulate` runs: a Simulator with a profile's units and generators, a
// FaultInjector as its fault hook, and the observers that print one line per request (or a
// periodic summary), and the traffic log that --record journals.
//
// Each request comes with the fault plan made for its answer (SimFaultPlanRecorder): its line
// says "dropped by fault" or which faults changed the answer.
class SimulateSession : public QObject
{
    Q_OBJECT
public:
    struct Options {
        bool quiet = false;
        int summaryIntervalMs = 10000; // --quiet: one summary line this often
    };

    SimulateSession(QTextStream &out, const Options &options, QObject *parent = nullptr);
    ~SimulateSession() override;

    // Units, generators, response delays and fault rules of the profile (the faults given
    // replace the profile's when set). False with *error set.
    bool load(const DeviceProfile &profile, const std::optional<FaultRuleSet> &faults, QString *error);
    // Binds every URL; false with *error naming the URL at fault (and what to do about it).
    bool listen(const QStringList &urls, QString *error);
    // Every frame in and out, and the fault plan of every answer, to log (simulate --record);
    // nullptr stops.
    void setTrafficLog(TrafficLog *log);
    // The inline tap: requests go to remote instead of the units (Simulator::setRemote), and each
    // answered line says what the remote noted (the device's own time). nullptr: the units again.
    void setRemote(SimRemote *remote);
    void start();
    void stop();

    // "rtu-tcp://127.0.0.1:4001 (units 1, 3)" per endpoint, as bound.
    [[nodiscard]] QStringList endpointDescriptions() const;
    [[nodiscard]] QString summary() const;
    [[nodiscard]] Simulator &simulator() { return m_sim; }
    [[nodiscard]] FaultInjector &faultInjector() { return m_injector; }
    [[nodiscard]] SimScriptDriver &scripts() { return m_scripts; }

private:
    struct Counts {
        quint64 requests = 0;
        quint64 answered = 0;
        quint64 exceptions = 0;
        quint64 noAnswer = 0;
        quint64 unknownUnit = 0;
        quint64 droppedByFault = 0;
        quint64 faulted = 0; // answered, but changed by a fault (delay, junk, wrong CRC...)
        quint64 malformed = 0;
        quint64 connections = 0;
        quint64 refused = 0;
    };

    void finish(const SimLogEntry &entry, const FaultPlan *plan);
    void count(const SimLogEntry &entry, const FaultPlan *plan);
    void printLine(const SimLogEntry &entry, const FaultPlan *plan);
    void printScriptLine(const QString &who, const QString &text, bool error);
    [[nodiscard]] QString verdictText(const SimLogEntry &entry, const FaultPlan *plan) const;
    [[nodiscard]] Framing framingOf(const QString &endpoint) const;

    QTextStream &m_out;
    Options m_options;
    Simulator m_sim;
    FaultInjector m_injector;
    GeneratorDriver m_driver;
    SimScriptDriver m_scripts; // the units' scripts: nothing without one
    QList<SimUnit *> m_units;
    // The injector as the fault hook, each request paired with the plan made for its answer.
    SimFaultPlanRecorder m_recorder{&m_sim, &m_injector};
    QHash<QString, Framing> m_framings;
    QTimer m_summaryTimer;
    QElapsedTimer m_elapsed;
    SimEndpointOptions m_endpointOptions;
    QSet<QString> m_delimited; // names of the endpoints serving a delimited protocol
    Counts m_counts;
    bool m_started = false;
    bool m_remote = false;
    QStringList m_heldLines; // script lines logged before start(), printed by it after the header
};

} // namespace mbscope::app
