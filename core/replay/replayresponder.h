#pragma once

#include "sim/faultplan.h"
#include "sim/simexchange.h"
#include "sim/simulator.h"

#include <QtCore/QByteArray>
#include <QtCore/QHash>
#include <QtCore/QList>

namespace mbscope {

class ReplayScript;

// The device side of replay: the Simulator answers with the recorded answers. It is the
// Simulator's fault hook (Simulator::setFaultHook), so every endpoint and framing the simulator
// has serves a recording; the units it adds are empty, their own answer is replaced here.
//
// A request is matched by unit and PDU, so an MBAP transaction id (or the recording's framing)
// does not matter. The same request recorded several times gets its recorded answers in turn,
// and again from the first after the last. A recorded silence (a timeout) is silence again.
// Requests never recorded get exception 0B (gateway target device failed to respond) or no
// answer at all, as the policy says; so do unit ids never recorded (SimEndpointOptions).
//
// Limits: the hook only sees requests the simulator's unit answers, so a request that puts an
// empty unit in listen-only mode (08/04) or restarts it (08/01) acts on that unit as well.
class ReplayResponder
{
public:
    enum class Unrecorded : quint8 { Exception0B, Ignore };
    struct Counters {
        quint64 served = 0;     // recorded answers sent
        quint64 silences = 0;   // recorded silences kept
        quint64 unrecorded = 0; // requests never recorded (answered 0B or ignored)
    };

    // speed: recorded latency divided by it before answering; 0 answers at once.
    ReplayResponder(const ReplayScript &script, Unrecorded policy, double speed);

    // Adds an empty unit for every recorded unit id and becomes sim's fault hook; the responder
    // must outlive the simulator's use of the hook.
    void install(Simulator &sim);
    // The endpoint options for that policy (units never recorded are treated alike).
    [[nodiscard]] SimEndpointOptions endpointOptions() const;
    // The plan for one request (the fault hook).
    [[nodiscard]] FaultPlan answer(const SimExchange &exchange);

    [[nodiscard]] const Counters &counters() const { return m_counters; }
    [[nodiscard]] qsizetype distinctRequests() const { return m_answers.size(); }
    // What the recording holds to serve: answers (normal or exception), and silences (requests
    // recorded without an answer, kept silent); together the script's size.
    [[nodiscard]] qsizetype recordedAnswers() const { return m_recordedAnswers; }
    [[nodiscard]] qsizetype recordedSilences() const { return m_recordedSilences; }
    [[nodiscard]] static QString policyText(Unrecorded policy); // "exception 0B", "no answer"

private:
    struct Recorded {
        Framing framing = Framing::Tcp;
        QByteArray adu;       // the recorded answer as it was; empty: no answer
        QByteArray pdu;       // its PDU, to re-frame for another framing
        qint64 latencyNs = 0;
    };
    struct Answers {
        QList<Recorded> inTurn;
        qsizetype next = 0;
    };
    [[nodiscard]] static QByteArray key(quint8 unitId, const QByteArray &pdu);
    [[nodiscard]] QByteArray frameFor(const Recorded &recorded, const SimExchange &exchange) const;

    QHash<QByteArray, Answers> m_answers;
    QList<quint8> m_unitIds;
    Unrecorded m_policy;
    double m_speed;
    Counters m_counters;
    qsizetype m_recordedAnswers = 0;
    qsizetype m_recordedSilences = 0;
};

} // namespace mbscope
