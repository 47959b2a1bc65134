// SimProcessor: Diagnostics (08), Get Comm Event Counter (0B), Get Comm Event Log (0C) and the
// bus-level counters an endpoint reports (V1.1b3 6.8-6.10).
#include "sim/simbytes.h"
#include "protocol/hexnumber.h"
#include "sim/simprocessor.h"
#include "sim/simunit.h"

namespace mbscope {

using simbytes::appendWord;
using simbytes::word;

namespace {

constexpr quint8 kEventRestart = 0x00;          // V1.1b3 6.10: communication restart
constexpr quint8 kEventEnteredListenOnly = 0x04;

QString subName(quint16 sub)
{
    return QStringLiteral("08/%1").arg(hexNumber(sub, 4));
}

} // namespace

void SimProcessor::noteBusMessage(SimUnit &unit)
{
    ++unit.counters().busMessages;
}

void SimProcessor::noteCommError(SimUnit &unit)
{
    ++unit.counters().busCommErrors;
    unit.logEvent(quint8(0x80 | 0x02 | (unit.isListenOnly() ? 0x20 : 0)));
}

void SimProcessor::noteOverrun(SimUnit &unit)
{
    ++unit.counters().busCharacterOverrun;
    unit.logEvent(quint8(0x80 | 0x10 | (unit.isListenOnly() ? 0x20 : 0)));
}

void SimProcessor::restart(bool clearEventLog)
{
    // V1.1b3 6.8.1 sub-function 01: the port restarts, the counters are cleared, listen-only
    // mode ends; with data FF00 the event log is cleared too. The restart itself is logged.
    m_pendingRestart.reset();
    m_unit->setListenOnly(false);
    m_unit->counters().clear();
    if (clearEventLog)
        m_unit->clearEventLog();
    m_unit->logEvent(kEventRestart);
}

SimReply SimProcessor::diagnostics(QByteArrayView pdu)
{
    if (pdu.size() < 3)
        return SimReply::exception(0x08, 0x03, QStringLiteral("08 needs a 2-byte sub-function, %1 data bytes given").arg(pdu.size() - 1));
    const quint16 sub = word(pdu, 1);
    const QByteArrayView data = pdu.sliced(3);
    const bool zeroData = data.size() == 2 && word(data, 0) == 0;
    auto badData = [&](const char *expected) {
        return SimReply::exception(0x08, 0x03, QStringLiteral("%1 takes data %2 (V1.1b3 6.8.1), got %3 bytes")
                                                   .arg(subName(sub), QLatin1String(expected))
                                                   .arg(data.size()));
    };
    auto echo = [&] { return SimReply::normal(pdu.toByteArray()); };
    SimCounters &counters = m_unit->counters();
    auto counter = [&](quint16 value) {
        QByteArray bytes(1, char(0x08));
        appendWord(bytes, sub);
        appendWord(bytes, value);
        return SimReply::normal(bytes);
    };
    // V1.1b3 6.8 state diagram: sub-function supported (else 01), then data value (else 03).
    switch (sub) {
    case 0x00: // Return Query Data: echo N words
        if (data.size() % 2 != 0)
            return badData("of whole 16-bit words");
        return echo();
    case 0x01: { // Restart Communications Option
        if (data.size() != 2 || (word(data, 0) != 0x0000 && word(data, 0) != 0xFF00))
            return badData("00 00 or FF 00");
        const bool wasListenOnly = m_unit->isListenOnly();
        m_pendingRestart = word(data, 0) == 0xFF00;
        if (wasListenOnly) {
            // "If the port is currently in Listen Only Mode, no response is returned."
            return SimReply::silent(QStringLiteral("08/0001 in listen-only mode: restarted without an answer"));
        }
        return echo();
    }
    case 0x02: // Return Diagnostic Register
        if (!zeroData)
            return badData("00 00");
        return counter(m_unit->diagnosticRegister());
    case 0x03: // Change ASCII Input Delimiter: CHAR 00
        if (data.size() != 2 || data[1] != 0)
            return badData("CHAR 00");
        m_unit->setAsciiDelimiter(data[0]);
        return echo();
    case 0x04: // Force Listen Only Mode: no response
        if (!zeroData)
            return badData("00 00");
        m_unit->setListenOnly(true);
        m_unit->logEvent(kEventEnteredListenOnly);
        return SimReply::silent(QStringLiteral("08/0004: listen-only mode entered, no answer until 08/0001"));
    case 0x0A: // Clear Counters and Diagnostic Register
        if (!zeroData)
            return badData("00 00");
        counters.clear();
        m_unit->setDiagnosticRegister(0);
        return echo();
    case 0x0B: return zeroData ? counter(counters.busMessages) : badData("00 00");
    case 0x0C: return zeroData ? counter(counters.busCommErrors) : badData("00 00");
    case 0x0D: return zeroData ? counter(counters.exceptionErrors) : badData("00 00");
    case 0x0E: return zeroData ? counter(counters.serverMessages) : badData("00 00");
    case 0x0F: return zeroData ? counter(counters.serverNoResponse) : badData("00 00");
    case 0x10: return zeroData ? counter(counters.serverNak) : badData("00 00");
    case 0x11: return zeroData ? counter(counters.serverBusy) : badData("00 00");
    case 0x12: return zeroData ? counter(counters.busCharacterOverrun) : badData("00 00");
    case 0x14: // Clear Overrun Counter and Flag
        if (!zeroData)
            return badData("00 00");
        counters.busCharacterOverrun = 0;
        return echo();
    default:
        return SimReply::exception(0x08, 0x01, QStringLiteral("%1 is not a sub-function the simulator serves (reserved, V1.1b3 6.8.1)")
                                                   .arg(subName(sub)));
    }
}

SimReply SimProcessor::commEventCounter(QByteArrayView pdu)
{
    if (pdu.size() != 1)
        return SimReply::exception(0x0B, 0x03, QStringLiteral("0B takes no data (V1.1b3 6.9), %1 bytes given").arg(pdu.size() - 1));
    QByteArray bytes(1, char(0x0B));
    appendWord(bytes, m_unit->isBusy() ? 0xFFFF : 0x0000);
    appendWord(bytes, m_unit->counters().commEventCounter);
    return SimReply::normal(bytes);
}

SimReply SimProcessor::commEventLog(QByteArrayView pdu)
{
    if (pdu.size() != 1)
        return SimReply::exception(0x0C, 0x03, QStringLiteral("0C takes no data (V1.1b3 6.10), %1 bytes given").arg(pdu.size() - 1));
    const QList<quint8> events = m_unit->eventLog(); // newest first, at most 64
    QByteArray bytes(1, char(0x0C));
    bytes.append(char(6 + events.size()));
    appendWord(bytes, m_unit->isBusy() ? 0xFFFF : 0x0000);
    appendWord(bytes, m_unit->counters().commEventCounter);
    appendWord(bytes, m_unit->counters().busMessages);
    for (quint8 e : events)
        bytes.append(char(e));
    return SimReply::normal(bytes);
}

} // namespace mbscope
