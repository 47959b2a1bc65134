#include "sim/simprocessor.h"

#include "protocol/hexnumber.h"
#include "sim/simbytes.h"
#include "sim/simmodbusserver.h"
#include "sim/simunit.h"

#include <QtSerialBus/QModbusPdu>

#include <optional>

namespace mbscope {

using simbytes::hexDec;
using simbytes::word;

namespace {

// Event log bytes, V1.1b3 6.10.
constexpr quint8 kReceiveEvent = 0x80;
// 0x02 (communication error) and 0x10 (character overrun) are never logged: the simulator
// receives whole frames from its endpoints and has no UART to report them.
constexpr quint8 kReceiveListenOnly = 0x20;
constexpr quint8 kReceiveBroadcast = 0x40;
constexpr quint8 kSendEvent = 0x40;
constexpr quint8 kSendReadException = 0x01;  // exception codes 1-3
constexpr quint8 kSendAbortException = 0x02; // code 4
constexpr quint8 kSendBusyException = 0x04;  // codes 5-6
constexpr quint8 kSendNakException = 0x08;   // code 7
constexpr quint8 kSendListenOnly = 0x20;

QString qtExceptionNote(quint8 functionCode, quint8 code)
{
    switch (code) {
    case 0x02:
        return QStringLiteral("function 0x%1: the addresses are outside the unit's map")
            .arg(hexNumber(functionCode, 2));
    case 0x03:
        return QStringLiteral("function 0x%1: the request's size, quantity, byte count or value is not allowed (V1.1b3 6.x)")
            .arg(hexNumber(functionCode, 2));
    default:
        return QStringLiteral("function 0x%1: exception 0x%2 from the server model")
            .arg(hexNumber(functionCode, 2))
            .arg(hexNumber(code, 2));
    }
}

struct WriteSpan {
    SimTable table;
    int start;
    int count;
};

// The addresses a write request touches, when the request passes its value checks (so that the
// read-only check comes after the 03 checks, as V1.1b3's state diagrams order them).
std::optional<WriteSpan> writeSpan(quint8 functionCode, QByteArrayView pdu)
{
    switch (functionCode) {
    case 0x05: // 6.5: value FF00 or 0000
        if (pdu.size() != 5 || (word(pdu, 3) != 0xFF00 && word(pdu, 3) != 0x0000))
            return std::nullopt;
        return WriteSpan{SimTable::Coils, word(pdu, 1), 1};
    case 0x06: // 6.6
        if (pdu.size() != 5)
            return std::nullopt;
        return WriteSpan{SimTable::HoldingRegisters, word(pdu, 1), 1};
    case 0x16: // 6.16
        if (pdu.size() != 7)
            return std::nullopt;
        return WriteSpan{SimTable::HoldingRegisters, word(pdu, 1), 1};
    case 0x0F: { // 6.11: 1-1968 coils, byte count = ceil(N / 8)
        if (pdu.size() < 6)
            return std::nullopt;
        const int quantity = word(pdu, 3);
        const int byteCount = quint8(pdu[5]);
        if (quantity < 1 || quantity > 0x07B0 || byteCount != (quantity + 7) / 8 || pdu.size() != 6 + byteCount)
            return std::nullopt;
        return WriteSpan{SimTable::Coils, word(pdu, 1), quantity};
    }
    case 0x10: { // 6.12: 1-123 registers, byte count = 2 x N
        if (pdu.size() < 6)
            return std::nullopt;
        const int quantity = word(pdu, 3);
        const int byteCount = quint8(pdu[5]);
        if (quantity < 1 || quantity > 0x007B || byteCount != quantity * 2 || pdu.size() != 6 + byteCount)
            return std::nullopt;
        return WriteSpan{SimTable::HoldingRegisters, word(pdu, 1), quantity};
    }
    default:
        return std::nullopt;
    }
}

} // namespace

SimProcessor::SimProcessor(SimUnit *unit)
    : m_unit(unit)
    , m_server(std::make_unique<SimModbusServer>(unit))
{
}

SimProcessor::~SimProcessor() = default;

SimReply SimProcessor::process(QByteArrayView pdu, bool broadcast)
{
    SimCounters &counters = m_unit->counters();
    ++counters.serverMessages;
    const bool listenOnly = m_unit->isListenOnly();
    m_unit->logEvent(quint8(kReceiveEvent | (broadcast ? kReceiveBroadcast : 0) | (listenOnly ? kReceiveListenOnly : 0)));
    if (pdu.isEmpty()) {
        ++counters.serverNoResponse;
        return SimReply::silent(QStringLiteral("empty PDU: no function code"));
    }
    const quint8 functionCode = quint8(pdu[0]);
    m_pendingRestart.reset();

    SimReply reply;
    if (listenOnly) {
        // V1.1b3 6.8.1, sub-function 04: in listen-only mode only 08/01 is processed.
        const bool restart = functionCode == 0x08 && pdu.size() >= 3 && word(pdu, 1) == 0x0001
                             && m_unit->supportsFunction(0x08);
        if (!restart) {
            ++counters.serverNoResponse;
            reply.kind = SimReply::Kind::ListenOnly;
            reply.note = QStringLiteral("unit %1 is in listen-only mode (08/04): only 08/01 brings it back").arg(m_unit->id());
            return reply;
        }
    }
    reply = dispatch(functionCode, pdu);
    if (listenOnly && reply.hasAnswer()) {
        // A refused 08/01 in listen-only mode: nothing is ever sent in that mode.
        reply.kind = SimReply::Kind::Silent;
        reply.pdu.clear();
        reply.note = QStringLiteral("listen-only mode: not answered (%1)").arg(reply.note);
    }
    if (broadcast && reply.hasAnswer()) {
        const QString was = reply.kind == SimReply::Kind::Exception
                                ? QStringLiteral(" (the answer would have been exception 0x%1: %2)")
                                      .arg(hexNumber(reply.exceptionCode, 2))
                                      .arg(reply.note)
                                : QString();
        reply.kind = SimReply::Kind::Silent;
        reply.pdu.clear();
        reply.note = QStringLiteral("broadcast: processed, never answered (Serial Line V1.02, 2.1)") + was;
    }
    account(functionCode, reply);
    if (m_pendingRestart)
        restart(*m_pendingRestart);
    return reply;
}

void SimProcessor::account(quint8 functionCode, const SimReply &reply)
{
    SimCounters &counters = m_unit->counters();
    quint8 event = kSendEvent | (m_unit->isListenOnly() ? kSendListenOnly : 0);
    switch (reply.kind) {
    case SimReply::Kind::Exception:
        ++counters.exceptionErrors;
        if (reply.exceptionCode == 0x06)
            ++counters.serverBusy;
        if (reply.exceptionCode == 0x07)
            ++counters.serverNak;
        if (reply.exceptionCode >= 1 && reply.exceptionCode <= 3)
            event |= kSendReadException;
        else if (reply.exceptionCode == 4)
            event |= kSendAbortException;
        else if (reply.exceptionCode == 5 || reply.exceptionCode == 6)
            event |= kSendBusyException;
        else if (reply.exceptionCode == 7)
            event |= kSendNakException;
        break;
    case SimReply::Kind::Normal:
        // V1.1b3 6.9: not incremented for exception responses or fetch event counter commands.
        if (functionCode != 0x0B && functionCode != 0x0C)
            ++counters.commEventCounter;
        break;
    case SimReply::Kind::Silent:
    case SimReply::Kind::ListenOnly:
        ++counters.serverNoResponse;
        break;
    }
    m_unit->logEvent(event);
}

SimReply SimProcessor::dispatch(quint8 functionCode, QByteArrayView pdu)
{
    if (!m_unit->supportsFunction(functionCode)) {
        return SimReply::exception(functionCode, 0x01,
                                   QStringLiteral("function code 0x%1 is not supported by unit %2")
                                       .arg(hexNumber(functionCode, 2))
                                       .arg(m_unit->id()));
    }
    if (m_unit->isBusy() && functionCode != 0x08 && functionCode != 0x0B && functionCode != 0x0C)
        return SimReply::exception(functionCode, 0x06, QStringLiteral("unit %1 is busy").arg(m_unit->id()));
    switch (functionCode) {
    case 0x03:
    case 0x04: return readRegisters(functionCode, pdu);
    case 0x01:
    case 0x02:
    case 0x05:
    case 0x06:
    case 0x0F:
    case 0x10:
    case 0x16:
        if (auto refused = checkWritable(functionCode, pdu))
            return *refused;
        return viaQt(functionCode, pdu);
    case 0x07: return readExceptionStatus(pdu);
    case 0x08: return diagnostics(pdu);
    case 0x0B: return commEventCounter(pdu);
    case 0x0C: return commEventLog(pdu);
    case 0x11: return reportServerId(pdu);
    case 0x14: return readFileRecord(pdu);
    case 0x15: return writeFileRecord(pdu);
    case 0x17: return readWriteRegisters(pdu);
    case 0x18: return readFifo(pdu);
    case 0x2B: return encapsulated(pdu);
    default:
        return SimReply::exception(functionCode, 0x01,
                                   QStringLiteral("function code 0x%1 is not implemented by the simulator")
                                       .arg(hexNumber(functionCode, 2)));
    }
}

std::optional<SimReply> SimProcessor::checkWritable(quint8 functionCode, QByteArrayView pdu) const
{
    const auto span = writeSpan(functionCode, pdu);
    if (!span || !m_unit->contains(span->table, span->start, span->count)
        || m_unit->isWritable(span->table, span->start, span->count))
        return std::nullopt;
    return SimReply::exception(functionCode, 0x02,
                               QStringLiteral("%1 %2 + %3 are read-only")
                                   .arg(QLatin1String(simTableName(span->table)), hexDec(span->start))
                                   .arg(span->count));
}

SimReply SimProcessor::viaQt(quint8 functionCode, QByteArrayView pdu)
{
    const QModbusRequest request(QModbusPdu::FunctionCode(functionCode), pdu.sliced(1).toByteArray());
    const QModbusResponse response = m_server->handle(request);
    if (response.isException()) {
        const quint8 code = quint8(response.exceptionCode());
        return SimReply::exception(functionCode, code, qtExceptionNote(functionCode, code));
    }
    QByteArray bytes;
    bytes.reserve(1 + response.dataSize());
    bytes.append(char(functionCode));
    bytes.append(response.data());
    return SimReply::normal(bytes);
}

SimReply SimProcessor::readRegisters(quint8 functionCode, QByteArrayView pdu)
{
    // QModbusServer's 03 and 04 (its readRegisters), without its answer encoded through
    // QDataStream and QBuffer: about 6,000 instructions per read, a third of the simulator's own
    // work per request under 50 clients (issue 15). Its checks in its order, its answers: a PDU
    // that is not 5 bytes or a quantity outside 1-125 (V1.1b3 6.3/6.4) exception 03, addresses
    // outside the map 02.
    if (pdu.size() != 5)
        return SimReply::exception(functionCode, 0x03, qtExceptionNote(functionCode, 0x03));
    const int start = word(pdu, 1);
    const int quantity = word(pdu, 3);
    if (quantity < 1 || quantity > 0x7D)
        return SimReply::exception(functionCode, 0x03, qtExceptionNote(functionCode, 0x03));
    const QList<quint16> values =
        m_unit->values(functionCode == 0x03 ? SimTable::HoldingRegisters : SimTable::InputRegisters, start, quantity);
    if (values.isEmpty())
        return SimReply::exception(functionCode, 0x02, qtExceptionNote(functionCode, 0x02));
    QByteArray bytes(2 + 2 * quantity, Qt::Uninitialized);
    char *out = bytes.data();
    *out++ = char(functionCode);
    *out++ = char(2 * quantity);
    for (const quint16 v : values) {
        *out++ = char(v >> 8);
        *out++ = char(v & 0xFF);
    }
    return SimReply::normal(bytes);
}

SimReply SimProcessor::readExceptionStatus(QByteArrayView pdu)
{
    if (pdu.size() != 1)
        return SimReply::exception(0x07, 0x03, QStringLiteral("07 takes no data (V1.1b3 6.7), %1 bytes given").arg(pdu.size() - 1));
    QByteArray bytes(2, 0);
    bytes[0] = 0x07;
    bytes[1] = char(m_unit->exceptionStatus());
    return SimReply::normal(bytes);
}

SimReply SimProcessor::reportServerId(QByteArrayView pdu)
{
    if (pdu.size() != 1)
        return SimReply::exception(0x11, 0x03, QStringLiteral("11 takes no data (V1.1b3 6.13), %1 bytes given").arg(pdu.size() - 1));
    // Byte count, server id, run indicator and additional data must fit a 253-byte PDU.
    QByteArray data = m_unit->serverId().left(250);
    data.append(char(m_unit->runIndicator() ? 0xFF : 0x00));
    data.append(m_unit->additionalData().left(251 - data.size()));
    QByteArray bytes;
    bytes.append(char(0x11));
    bytes.append(char(data.size()));
    bytes.append(data);
    return SimReply::normal(bytes);
}

} // namespace mbscope
