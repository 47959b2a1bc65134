#pragma once

#include "profile/devicelimits.h"
#include "profile/linerule.h"
#include "sim/lineresponder.h"
#include "protocol/streamframe.h"
#include "sim/faultplan.h"
#include "sim/simendpointoptions.h"
#include "sim/simexchange.h"
#include "sim/simlogentry.h"
#include "sim/simremote.h"
#include "protocol/adubuilder.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QVarLengthArray>

#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace mbscope {

class LinkUrl;
class ScriptHost;
class SimEndpoint;
class SimProcessor;
class SimUnit;
class TrafficLog;
enum class TrafficVerdict : quint8;

// The built-in device simulator: units (SimUnit, each with its SimProcessor) behind endpoints
// (SimEndpoint: tcp://, rtu-tcp://, ascii-tcp://, tls://, udp://, rtu-udp://, rtu://, ascii://).
// Every endpoint reaches every unit unless its options name some (a gateway); requests to a unit
// nobody has get exception 0B or silence (SimEndpointOptions::unknownUnit). On serial framings
// (RTU and ASCII, also over TCP and UDP) unit 0 is a broadcast: every unit processes it, none
// answers (Serial Line V1.02, 2.1).
//
//     Simulator sim;
//     SimUnit *unit = sim.addUnit(1);            // fill it: ranges, device id... (or a profile)
//     SimEndpoint *tcp = sim.listen(QStringLiteral("tcp://127.0.0.1:0"), {}, &error);
//     quint16 port = tcp->boundUrl().port;        // the port the OS chose
//
// Faults: setFaultHook() sees each answer before it leaves (SimExchange) and returns the
// FaultPlan to execute; without a hook the answer leaves after the unit's response delay.
// Time never blocks: delays and chunks run on timers.
class Simulator : public QObject
{
    Q_OBJECT
public:
    using FaultHook = std::function<FaultPlan(const SimExchange &exchange)>;

    explicit Simulator(QObject *parent = nullptr);
    ~Simulator() override;

    // ---- Units ----
    // A new empty unit (ids 1-255; 0 is the serial broadcast address), or nullptr when the id is
    // taken or 0.
    SimUnit *addUnit(quint8 id);
    // Takes a unit built elsewhere (a profile loader); nullptr (and the unit deleted) when its id
    // is taken or 0.
    SimUnit *adoptUnit(std::unique_ptr<SimUnit> unit);
    void removeUnit(quint8 id);
    [[nodiscard]] SimUnit *unit(quint8 id) const;
    [[nodiscard]] QList<quint8> unitIds() const;

    // ---- Endpoints ----
    // Parses the URL for listening (LinkUse::Listen: port 0 lets the OS choose, no host means
    // 127.0.0.1), binds and starts. nullptr with *error set on failure.
    SimEndpoint *listen(const QString &url, const SimEndpointOptions &options = {}, QString *error = nullptr);
    SimEndpoint *listen(const LinkUrl &url, const SimEndpointOptions &options = {}, QString *error = nullptr);
    [[nodiscard]] QList<SimEndpoint *> endpoints() const { return m_endpoints; }
    void closeEndpoint(SimEndpoint *endpoint);
    void closeAll();

    // ---- Device limits (DeviceLimits: the minimum gap, the largest quantities, the warm-up) ----
    // The unknown-unit and client limits belong to the endpoints (SimEndpointOptions,
    // ProfileApplier::endpointOptions). The gap is the device's, across every endpoint: it runs
    // from the arrival of the last request the device took.
    void setLimits(const DeviceLimits &limits) { m_limits = limits; }
    [[nodiscard]] const DeviceLimits &limits() const { return m_limits; }

    // ---- Delimited protocols ----
    // The requests and answers of a non-Modbus protocol (LineTable), served on endpoints whose
    // URL says framing=delimited; listen() refuses such an endpoint while the table is empty.
    void setLineTable(const LineTable &table) { m_lineTable = table; }
    [[nodiscard]] const LineTable &lineTable() const { return m_lineTable; }

    // ---- Scripts (SimScriptDriver: docs/profiles.md, "Scripts") ----
    // A unit's script (not owned; nullptr removes it) sees each request the unit takes, after the
    // device limits, and answers before the unit's data model does. Units without one pay nothing.
    void setScript(quint8 unitId, ScriptHost *script);
    [[nodiscard]] ScriptHost *script(quint8 unitId) const;
    // A delimited protocol's script (onFrame) speaks before the LineTable; with it, listen()
    // takes framing=delimited without a table.
    void setLineScript(ScriptHost *script) { m_lineScript = script; }
    [[nodiscard]] ScriptHost *lineScript() const { return m_lineScript; }

    // ---- Faults and logs ----
    void setFaultHook(FaultHook hook) { m_faultHook = std::move(hook); }
    [[nodiscard]] bool hasFaultHook() const { return bool(m_faultHook); }
    // Frames in and out are appended to log (not owned; nullptr stops). Same thread only.
    // Directions are the simulator's: a request comes In, its answer goes Out; each request
    // gets a transaction id of its own (1, 2, 3...) that its answer's frames carry, an
    // unanswered one an empty Out record (verdict Timeout, or Broadcast), and the fault plan
    // that shaped an answer a note (TrafficLog::annotate): {"faults": [...], "drop": true,
    // "close": "before"|"after", "chunks": N, "delay_ms": D}. An answer sent in pieces (the
    // chunks and trickle rules, or a duplicate) is one Out frame per piece, each logged as it
    // is written with its own time: the journal says what the wire carried, and its reader
    // (JournalExchangeReader) joins the pieces into the answer the client's framer made.
    void setTrafficLog(TrafficLog *log);

    // ---- A remote (the inline tap) ----
    // Requests no longer go to the units but to remote (not owned; nullptr: the units again),
    // which answers when it can (SimRemote). Checks, logs, the fault hook and the endpoints'
    // writing stay the simulator's. Delimited endpoints keep their line table.
    void setRemote(SimRemote *remote) { m_remote = remote; }
    [[nodiscard]] SimRemote *remote() const { return m_remote; }

    // ---- The request path (used by the endpoints; public for tests and fuzzing) ----
    // What the endpoints call: sink gets the plan to execute, at once (the units answer
    // synchronously) or later (a remote's answer); not at all when the simulator or the endpoint
    // is gone by then. The endpoint must check that its output still exists when sink runs.
    // True when takeFrame would call its sink at once with handleFrame's plan (no remote, or a
    // delimited endpoint): the endpoint may then call handleFrame itself and build no sink.
    [[nodiscard]] bool answersLocally(const SimEndpoint *endpoint) const;
    using PlanSink = std::function<void(const FaultPlan &plan)>;
    void takeFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status, const QString &peer,
                   qint64 receivedNs, qint64 connectedNs, const PlanSink &sink);
    // One frame cut by the endpoint's framer (or one datagram), answered by the units (the remote
    // is not asked: takeFrame asks it). Returns what to send: a plan
    // with drop set for silence. connectedNs: when the client's connection opened (the warm-up
    // runs from it); 0: when the endpoint started.
    FaultPlan handleFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status,
                          const QString &peer, qint64 receivedNs, qint64 connectedNs = 0);
    // Bytes the framer skipped: logged, and on serial framings counted (a CRC mismatch is a comm
    // error, a frame too long an overrun).
    void noteSkipped(SimEndpoint *endpoint, const SkippedBytes &skipped, const QString &peer);
    // Connection events and bytes sent, for the logs.
    void noteConnection(SimEndpoint *endpoint, const QString &peer, SimLogEntry::Verdict verdict,
                        const QString &reason);
    // trafficId: FaultPlan::trafficId of the request answered (0: none).
    void noteSent(SimEndpoint *endpoint, const QByteArray &bytes, quint64 trafficId = 0);

Q_SIGNALS:
    // Every request, answer and connection event, as it happens.
    void logged(const mbscope::SimLogEntry &entry);

private:
    struct Slot {
        std::unique_ptr<SimUnit> unit;
        std::unique_ptr<SimProcessor> processor;
        ScriptHost *script = nullptr;
    };
    // The units an endpoint serves; inline up to 8, so that a request allocates no list.
    using SlotList = QVarLengthArray<Slot *, 8>;
    [[nodiscard]] SlotList slotsOf(const SimEndpoint *endpoint);
    // Returns the traffic id the request was logged with (0: no traffic log, or no request).
    quint64 log(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView request,
                const QByteArray &response, SimLogEntry::Verdict verdict, const QString &reason,
                const QStringList &faults = {});
    // log()'s parts: the request into the traffic log (its id; 0 without a log), the empty answer
    // record of an unanswered one, and the logged() entry.
    quint64 logArrival(SimEndpoint *endpoint, const QString &peer, QByteArrayView request, TrafficVerdict verdict, qint64 tNs);
    void logUnanswered(SimEndpoint *endpoint, quint64 id, bool broadcast, qint64 tNs);
    void emitEntry(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView request,
                   const QByteArray &response, SimLogEntry::Verdict verdict, const QString &reason,
                   const QStringList &faults = {});
    // The frame checks every request passes first (checksum, MBAP header, a function code):
    // false, logged, when it is dropped; *out holds its parts.
    bool acceptModbusFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status, const QString &peer,
                           const SlotList &units, AduParts *out);
    // A request the remote is answering.
    struct Pending {
        QPointer<SimEndpoint> endpoint;
        QString peer;
        QByteArray adu;
        AduParts parts;
        qint64 receivedNs = 0;
        qint64 intervalNs = -1;
        quint64 trafficId = 0;
        PlanSink sink;
    };
    void finishForward(const Pending &pending, const SimRemote::Answer &answer);
    void noteFaultPlan(SimEndpoint *endpoint, const FaultPlan &plan);
    [[nodiscard]] quint16 trafficLink(const SimEndpoint *endpoint);

    // A reply refusing the request by the device limits (gap, quantity), or nullopt to go on.
    [[nodiscard]] std::optional<SimReply> limitReply(const QByteArray &pdu, qint64 receivedNs, bool *silent);

    // The line script's answer to a delimited frame (body without checksum), nullopt for the
    // table's; *delayNs its delay (-1: the unit's).
    [[nodiscard]] std::optional<LineAnswer> lineScriptAnswer(const QByteArray &body, int unitId, qint64 *delayNs);
    FaultPlan handleLine(SimEndpoint *endpoint, QByteArrayView frame, FrameStatus status, const QString &peer,
                         qint64 receivedNs, qint64 connectedNs);
    // Whether a request at receivedNs falls in the warm-up (then logged as ignored).
    bool warmingUp(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView adu, qint64 receivedNs,
                   qint64 connectedNs);

    std::map<quint8, Slot> m_units;
    DeviceLimits m_limits;
    LineTable m_lineTable;
    ScriptHost *m_lineScript = nullptr;
    qint64 m_lastTakenNs = 0; // arrival of the last request the device took (minGapMs)
    // Arrival of the last request on each endpoint: the interval time-dependent faults go by.
    QHash<const SimEndpoint *, qint64> m_lastArrivalNs;
    [[nodiscard]] qint64 intervalSince(const SimEndpoint *endpoint, qint64 receivedNs);
    QList<SimEndpoint *> m_endpoints;
    FaultHook m_faultHook;
    SimRemote *m_remote = nullptr;
    TrafficLog *m_trafficLog = nullptr;
    QHash<const SimEndpoint *, quint16> m_trafficLinks;
    QHash<quint16, QString> m_trafficPeers; // by link: the client of its last request
    quint64 m_lastTrafficId = 0;
};

} // namespace mbscope
