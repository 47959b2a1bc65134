#pragma once

#include "protocol/framing.h"
#include "profile/delayspec.h"
#include "sim/faultplan.h"
#include "profile/faultrule.h"
#include "sim/simrandom.h"

#include <QtCore/QByteArray>
#include <QtCore/QMap>
#include <QtCore/QMutex>

#include <vector>

namespace mbscope {

struct SimExchange;

// What the fault injector is told about one answer.
struct FaultContext {
    Framing framing = Framing::Tcp; // Rtu for rtu://, rtu-tcp and rtu-udp; Tcp for tcp and tls; Udp; Ascii
    // framing=delimited: the request and answer are a delimited protocol's frames, not Modbus; rules
    // that change Modbus fields (exception, fewer registers, wrong unit, transaction id or
    // checksum) do not apply, and function and addresses stay unset.
    bool delimited = false;
    quint8 unit = 0;                // the unit that answers (per-unit delays and rules follow it)
    quint8 function = 0;            // the request's function code
    int firstAddress = -1;          // the addresses the request touches; -1: none (07, 11, 2B...)
    int lastAddress = -1;
    // The request's fields as written, for exact matching: the start address (01-06, 0F, 10, 16;
    // 17 the read start; 18 the FIFO pointer), the quantity (01-04, 0F, 10; 17 the read
    // quantity; 05 and 06 one), and the values written (05: 1 for FF00, 0 for 0000; 06 the
    // register; 0F the bits as 0 and 1; 10 and 17 the registers; 16 the AND and OR masks).
    int start = -1;
    int quantity = -1;
    QList<quint16> written;
    bool writes = false;
    QByteArray request;             // the request ADU
    QByteArray response;            // the correct response ADU
    qint64 responseDelayNs = 0;     // the unit's response time when no distribution is set for it
    bool responseDelayFixed = false; // a script set responseDelayNs: the unit's distribution does not replace it
    // Since the previous request arrived on the same endpoint (the bus); -1: none before. Rules
    // with byIntervalMs or a turnaround fire by it.
    qint64 intervalNs = -1;

    // unit, function and addresses read from the request ADU: 01-04, 0F, 10 start and quantity;
    // 05, 06, 16 the address; 17 from the lower start to the higher end of read and write; 18
    // the FIFO pointer address.
    [[nodiscard]] static FaultContext forRequest(Framing framing, const QByteArray &request,
                                                 const QByteArray &response, qint64 responseDelayNs = 0);
    // The same for what the simulator made of a request, with unit the unit that answers
    // (SimExchange::routedUnitId: unit 0 or 255 over MBAP is answered by the endpoint's first
    // unit, whose response delay and fault rules apply).
    [[nodiscard]] static FaultContext forExchange(const SimExchange &exchange);
};

// Decides what happens to each answer of the simulator: plan() turns the correct response ADU
// into a FaultPlan (chunks of bytes with delays, or silence, or a closed connection) by the rules
// in force. Reproducible: each rule draws from its own random stream derived from the rule set's
// seed and the rule's index, each unit's response delay from a stream of its own, so the same
// requests give the same plans, and a rule that never matches changes nothing for the others.
//
// setRules() may be called while the simulator runs (from any thread: plan() and setRules() are
// serialised by a mutex); it restarts the random streams.
//
// The effects of the rules that fire on one answer combine in this order, whatever their order
// in the list: drop and close-before (no answer); exception, fewer registers, wrong unit (the
// PDU and unit, checksum and length recomputed); wrong transaction id and wrong checksum (the
// bytes as sent); delay (the last delay rule that fired replaces the unit's response time);
// junk before/after; duplicates; close midway (the first half of the bytes, then close);
// trickle or chunks (trickle wins); close after. Noise acts on the request first (a request with a
// flipped bit is lost: no answer, as a slave discards a frame that fails its checks) and on the
// answer after the content changes (its bytes as sent, so a CRC or BCC then fails as it would).
// A rule with byIntervalMs or a turnaround fires by FaultContext::intervalNs instead of its
// probability.
class FaultInjector
{
public:
    FaultInjector() = default;

    void setRules(const FaultRuleSet &rules);
    [[nodiscard]] FaultRuleSet rules() const;
    // A unit's response time distribution (from its profile); restarts that unit's stream.
    void setResponseDelay(quint8 unit, const DelaySpec &delay);
    void clearResponseDelays();
    // Every random stream back to its start.
    void reset();

    [[nodiscard]] FaultPlan plan(const FaultContext &context);
    // The same for a simulator's exchange: without rules, the plan is made from the exchange as
    // it is (no FaultContext, whose request is parsed again, per request).
    [[nodiscard]] FaultPlan plan(const SimExchange &exchange);

    // Whether rule could apply to this answer (unit, function, the addresses it meets, its exact
    // start, quantity and written values, and what the fault needs: a checksum, an MBAP header,
    // a read answer...).
    [[nodiscard]] static bool matches(const FaultRule &rule, const FaultContext &context);

    // Whether a matching rule fires on this answer: by its probability, its byIntervalMs table or
    // its turnaround, drawing from random.
    [[nodiscard]] static bool fires(const FaultRule &rule, const FaultContext &context, SimRandom &random);

private:
    [[nodiscard]] SimRandom &delayRandom(quint8 unit);
    // No rule: the answer after the unit's response time (m_mutex held).
    [[nodiscard]] FaultPlan planWithoutRules(quint8 unit, const QByteArray &response, qint64 responseDelayNs, bool delayFixed);
    void resetStreams(); // with m_mutex held

    mutable QMutex m_mutex;
    FaultRuleSet m_rules;
    std::vector<SimRandom> m_ruleRandom;
    QMap<quint8, DelaySpec> m_delays;
    QMap<quint8, SimRandom> m_delayRandom;
};

} // namespace mbscope
