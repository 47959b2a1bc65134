#include "mapscanner.h"

#include "unitscanner.h"

#include "protocol/adubuilder.h"
#include "protocol/readanswer.h"
#include "protocol/functionspec.h"

namespace mbscope {

namespace {

struct OptionalProbe {
    quint8 function;
    int sub;
    QByteArray pdu;
    const char *note;
};

// The optional functions asked, each in a form that reads and changes nothing (V1.1b3 sections
// 6.7-6.21); 08/01 (restart), 08/0A (clear counters), 15 and 16 are writes of a kind and never sent.
QList<OptionalProbe> optionalProbes()
{
    QList<OptionalProbe> probes{
        {0x07, -1, QByteArray::fromHex("07"), "read exception status"},
        {0x08, 0x00, QByteArray::fromHex("0800001234"), "return query data"},
        {0x08, 0x02, QByteArray::fromHex("0800020000"), "return diagnostic register"},
    };
    for (int sub = 0x0B; sub <= 0x12; ++sub) {
        QByteArray pdu = QByteArray::fromHex("0800");
        pdu.append(char(sub)).append('\0').append('\0');
        probes.append({0x08, sub, pdu, "a diagnostic counter"});
    }
    probes.append({0x0B, -1, QByteArray::fromHex("0B"), "get comm event counter"});
    probes.append({0x0C, -1, QByteArray::fromHex("0C"), "get comm event log"});
    probes.append({0x11, -1, QByteArray::fromHex("11"), "report server id"});
    probes.append({0x14, -1, QByteArray::fromHex("140706000100000001"), "read file 1, record 0"});
    probes.append({0x17, -1, QByteArray::fromHex("1700000001000000000000"),
                   "read 1 register, write quantity 0: refused (03) before anything is written"});
    probes.append({0x18, -1, QByteArray::fromHex("180000"), "read FIFO queue at 0"});
    probes.append({0x2B, 0x0E, QByteArray::fromHex("2B0E0100"), "read device identification, basic"});
    return probes;
}

} // namespace

MapScanner::MapScanner(QObject *parent)
    : QObject(parent)
    , m_channel(new ProbeChannel(this))
{
}

std::optional<RegisterMap> MapScanner::run(const MapScanSettings &settings)
{
    if (!settings.problem().isEmpty())
        return std::nullopt;
    m_settings = settings;
    m_channel->setTarget(settings.url);
    m_channel->setGapMs(settings.gapMs);
    m_requests = 0;
    m_stopRequested = false;
    m_end = JobEnd::Completed;
    m_linkProblem.clear();
    m_clock.start();

    RegisterMap map;
    map.unit = settings.unit;
    for (m_tableIndex = 0; m_tableIndex < settings.functions.size() && mayContinue(); ++m_tableIndex) {
        TableMap table;
        table.function = settings.functions.at(m_tableIndex);
        table.searchedFirst = settings.firstAddress;
        table.searchedLast = settings.lastAddress;
        const int before = m_requests;
        mapTable(table);
        table.requests = m_requests - before;
        map.tables.append(table);
    }
    // A gateway that answered every table for the unit with 0A or 0B has no device behind it to
    // ask the optional functions of.
    bool noDevice = !map.tables.isEmpty();
    for (const TableMap &t : std::as_const(map.tables))
        noDevice = noDevice && t.gatewayException != 0;
    if (settings.optionalFunctions && !noDevice && mayContinue())
        probeOptional(map);
    map.requests = m_requests;
    m_channel->closeLink();
    report(int(settings.functions.size()), settings.firstAddress);
    return map;
}

bool MapScanner::mayContinue()
{
    if (m_end != JobEnd::Completed)
        return false;
    if (m_stopRequested)
        m_end = JobEnd::Stopped;
    else if (m_requests >= m_settings.maxRequests)
        m_end = JobEnd::RequestLimit;
    else if (m_clock.elapsed() + m_settings.timeoutMs + m_settings.gapMs > m_settings.maxDurationMs)
        m_end = JobEnd::TimeLimit;
    return m_end == JobEnd::Completed;
}

std::optional<ProbeChannel::Answer> MapScanner::ask(const QByteArray &pdu)
{
    if (!mayContinue())
        return std::nullopt;
    ++m_requests;
    std::optional<ProbeChannel::Answer> answer = m_channel->ask(m_settings.unit, pdu, m_settings.timeoutMs);
    if (!answer) {
        m_stopRequested = true;
        return std::nullopt;
    }
    if (answer->transaction.status == TransactionStatus::LinkError) {
        m_end = JobEnd::LinkError;
        if (m_linkProblem.isEmpty())
            m_linkProblem = answer->transaction.problem;
    }
    return answer;
}

MapScanner::ReadReply MapScanner::read(quint8 function, int address, int quantity)
{
    ReadReply reply;
    const std::optional<ProbeChannel::Answer> answer =
        ask(UnitScanner::readPdu(function, quint16(address), quint16(quantity)));
    if (!answer)
        return reply;
    const Transaction &t = answer->transaction;
    switch (t.status) {
    case TransactionStatus::Ok: {
        const QByteArray pdu = AduBuilder::parse(t.response, m_settings.url.framing()).pdu;
        const ReadAnswerResult parsed = ReadAnswer::fromResponse(function, address, quantity, pdu);
        if (!parsed.ok) {
            reply.reply = Reply::Bad;
            break;
        }
        reply.reply = Reply::Ok;
        if (parsed.answer.isBits()) {
            for (const bool b : parsed.answer.bits)
                reply.values.append(b ? 1 : 0);
        } else {
            reply.values = parsed.answer.registers;
        }
        break;
    }
    case TransactionStatus::Exception:
        reply.exceptionCode = t.exceptionCode;
        reply.reply = t.exceptionCode == 0x02 ? Reply::IllegalAddress
            : t.exceptionCode == 0x03         ? Reply::IllegalQuantity
            : t.exceptionCode == 0x01         ? Reply::IllegalFunction
                                              : Reply::OtherException;
        break;
    case TransactionStatus::Timeout:
        reply.reply = Reply::Silent;
        break;
    default:
        reply.reply = Reply::Bad;
        break;
    }
    return reply;
}

int MapScanner::findMaxQuantity(TableMap &table, int specMax)
{
    const int address = qMin(table.searchedFirst, 65536 - specMax);
    const ReadReply full = read(table.function, address, specMax);
    if (full.reply != Reply::IllegalQuantity)
        return full.reply == Reply::Silent || full.reply == Reply::Bad ? 0 : specMax;
    int ok = 1;
    int refused = specMax;
    while (refused - ok > 1 && mayContinue()) {
        const int mid = (ok + refused) / 2;
        if (read(table.function, address, mid).reply == Reply::IllegalQuantity)
            refused = mid;
        else
            ok = mid;
    }
    return ok;
}

void MapScanner::mapTable(TableMap &table)
{
    const int first = table.searchedFirst;
    const ReadReply probe = read(table.function, first, 1);
    if (probe.reply == Reply::IllegalFunction || probe.reply == Reply::Silent || probe.reply == Reply::Bad)
        return;
    if (probe.reply == Reply::OtherException && (probe.exceptionCode == 0x0A || probe.exceptionCode == 0x0B)) {
        table.gatewayException = probe.exceptionCode; // a gateway with no device behind it for this unit
        return;
    }
    table.supported = true;
    const int specMax = QuantityLimits::maxQuantity(quint8(table.function));
    table.maxQuantity = findMaxQuantity(table, specMax);

    // Between blocks, one address every `step`; an address that answers may belong to a block that
    // began after the last address asked, found by bisection: a read from x to the hit answers only
    // when every address between exists.
    const int step = qBound(1, m_settings.step, qMax(1, table.maxQuantity));
    int address = first;
    int unknownFrom = first; // the first address not yet known to be missing
    ReadReply reply = probe;
    while (address <= table.searchedLast && mayContinue()) {
        report(m_tableIndex, address);
        if (address != first)
            reply = read(table.function, address, 1);
        if (reply.reply != Reply::Ok) {
            // A read past a block refused with 02: if another block follows, reads over the gap fail.
            if (reply.reply == Reply::IllegalAddress && !table.blocks.isEmpty() && table.firstGapRefusal < 0)
                table.firstGapRefusal = address;
            unknownFrom = address + 1;
            address = address == table.searchedLast ? address + 1 : qMin(address + step, table.searchedLast);
            continue;
        }
        int start = address;
        QList<quint16> values = reply.values;
        int lo = unknownFrom;
        while (lo < start && mayContinue()) {
            const int mid = (lo + start) / 2;
            const ReadReply r = read(table.function, mid, address - mid + 1);
            if (r.reply == Reply::Ok) {
                start = mid;
                values = r.values;
            } else {
                lo = mid + 1;
            }
        }
        const MapBlock block = extendBlock(table, start, values);
        table.blocks.append(block);
        address = block.last() + 1;
        unknownFrom = address;
    }
}

MapBlock MapScanner::extendBlock(TableMap &table, int address, QList<quint16> firstValues)
{
    MapBlock block;
    block.address = quint16(address);
    block.values = std::move(firstValues);
    const int maxQ = qMax(1, table.maxQuantity);
    // Galloping from the first address: twice the addresses known, then twice again, until a read
    // is refused or the largest quantity is reached.
    int pos = address;
    int known = int(block.values.size()); // addresses from pos known to exist, their values in block.values
    int q = 2 * known;
    for (;;) {
        const int cap = qMin(maxQ, table.searchedLast - pos + 1);
        if (known >= cap) {
            if (cap < maxQ) // the end of the search
                return block;
            // A whole read's worth exists: the block goes on from the next address, read whole.
            pos += known;
            known = 0;
            q = qMin(maxQ, table.searchedLast - pos + 1);
            if (q <= 0)
                return block;
        }
        q = qMin(q, qMin(maxQ, table.searchedLast - pos + 1));
        if (!mayContinue())
            return block;
        const ReadReply r = read(table.function, pos, q);
        if (r.reply == Reply::Ok) {
            block.values = block.values.mid(0, pos - address) + r.values;
            known = q;
            q *= 2;
            continue;
        }
        // The block ends between pos + known and pos + q: bisection.
        int ok = known;
        int refused = q;
        while (refused - ok > 1 && mayContinue()) {
            const int mid = (ok + refused) / 2;
            const ReadReply m = read(table.function, pos, mid);
            if (m.reply == Reply::Ok) {
                block.values = block.values.mid(0, pos - address) + m.values;
                ok = mid;
            } else {
                refused = mid;
            }
        }
        block.values = block.values.mid(0, pos - address + ok);
        return block;
    }
}

void MapScanner::probeOptional(RegisterMap &map)
{
    for (const OptionalProbe &p : optionalProbes()) {
        FunctionSupport support;
        support.function = p.function;
        support.subFunction = p.sub;
        support.note = QString::fromLatin1(p.note);
        const std::optional<ProbeChannel::Answer> answer = ask(p.pdu);
        if (!answer)
            break;
        const Transaction &t = answer->transaction;
        if (t.status == TransactionStatus::Ok) {
            support.answer = FunctionSupport::Answer::Answers;
            const QByteArray pdu = AduBuilder::parse(t.response, m_settings.url.framing()).pdu;
            if (p.function == 0x07 && pdu.size() >= 2)
                map.exceptionStatus = quint8(pdu.at(1));
            if (p.function == 0x11 && pdu.size() >= 2)
                map.serverIdData = pdu.mid(2, quint8(pdu.at(1)));
        } else if (t.status == TransactionStatus::Exception) {
            support.answer = FunctionSupport::Answer::Exception;
            support.exceptionCode = t.exceptionCode;
        } else {
            support.answer = FunctionSupport::Answer::Silent;
        }
        map.functions.append(support);
    }
    for (const quint8 f : {quint8(0x15), quint8(0x16)}) {
        FunctionSupport support;
        support.function = f;
        support.answer = FunctionSupport::Answer::NotProbed;
        support.note = QStringLiteral("every request of this function writes: never sent by a scan");
        map.functions.append(support);
    }
}

void MapScanner::report(int tableIndex, int address)
{
    const int window = m_settings.lastAddress - m_settings.firstAddress + 1;
    JobProgress p;
    p.total = int(m_settings.functions.size()) * window;
    p.done = qMin(p.total, tableIndex * window + (address - m_settings.firstAddress));
    p.elapsedMs = m_clock.elapsed();
    p.remainingMs = p.done > 0 ? p.elapsedMs * (p.total - p.done) / p.done : 0;
    p.remainingMs = qMin(p.remainingMs, qMax<qint64>(0, m_settings.maxDurationMs - p.elapsedMs));
    Q_EMIT progressChanged(p);
}

} // namespace mbscope

#include "moc_mapscanner.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
