#include "journalexchangereader.h"

#include <QtCore/qnumeric.h>

#include <algorithm>

#include "exchange/responseverdict.h"
#include "traffic/trafficmetadata.h"
#include "transport/linkurl.h"

#include <QtCore/QFile>
#include <QtCore/QHash>
#include <QtNetwork/QHostAddress>
#include <QtCore/QtEndian>

#include <deque>
#include <memory>
#include <utility>

namespace mbscope {

namespace {

struct Slot {
    CaptureExchange exchange;
    bool done = false;
};

CaptureConversation conversationFor(quint16 link, const QString &name)
{
    CaptureConversation c;
    c.id = link;
    c.client.bytes = {10, 0, 0, 1};
    c.clientPort = quint16(49152 + link);
    c.server.bytes = {10, 0, 0, 2};
    c.serverPort = 502;
    const LinkUrl::Result parsed = LinkUrl::parse(name);
    if (!parsed.url)
        return c;
    const LinkUrl &url = *parsed.url;
    c.framing = url.framing();
    c.udp = url.isDatagram();
    if (!url.isSerial())
        c.serverPort = url.port;
    else
        c.serverPort = 4001; // a serial line has no port: the one serial device servers use most
    bool ok = false;
    const quint32 v4 = QHostAddress(url.host).toIPv4Address(&ok);
    if (ok && v4 != 0x0a000001)
        c.server.bytes = {quint8(v4 >> 24), quint8(v4 >> 16), quint8(v4 >> 8), quint8(v4)};
    return c;
}

} // namespace

bool JournalExchangeReader::isJournal(QByteArrayView firstBytes)
{
    return firstBytes.startsWith("MBSCTLOG");
}

namespace {

constexpr qint64 kMaxWallNs = qint64(1) << 62;

} // namespace

JournalExchangeReader::Result JournalExchangeReader::read(const QString &path, const Sink &sink,
                                                          const std::function<void(const CaptureConversation &)> &onConversation)
{
    Result result;
    // The header's clock pair turns monotonic ns into wall-clock ns; the reader gives it only at
    // the end, so it is read here first (trafficjournal.h: wall ms at 16, monotonic ns at 24).
    qint64 wallNs = 0;
    qint64 monotonicNs = 0;
    {
        QFile file(path);
        if (file.open(QIODevice::ReadOnly)) {
            const QByteArray header = file.read(40);
            if (header.size() == 40) {
                // A damaged header (fuzz_journal found one) must not overflow: wall-clock times
                // are kept within 1970 .. 1970 + 2^62 ns, as capture time stamps are.
                const qint64 wallMs = qFromLittleEndian<qint64>(header.constData() + 16);
                wallNs = std::clamp<qint64>(wallMs, 0, kMaxWallNs / 1000000) * 1000000;
                monotonicNs = qFromLittleEndian<qint64>(header.constData() + 24);
            }
        }
    }
    const auto wall = [&](qint64 tNs) {
        qint64 delta = 0;
        if (qSubOverflow(tNs, monotonicNs, &delta))
            delta = tNs > monotonicNs ? kMaxWallNs : -kMaxWallNs;
        qint64 ns = 0;
        if (qAddOverflow(wallNs, delta, &ns))
            ns = delta > 0 ? kMaxWallNs : 0;
        return std::clamp<qint64>(ns, 0, kMaxWallNs);
    };

    std::deque<Slot> queue;
    quint64 firstSlot = 1;
    // A transaction is its link and its id: the engines of one journal (a watch run's links, a
    // scan's clients) each number theirs from 1.
    using Key = std::pair<quint16, quint64>;
    QHash<Key, quint64> waiting; // link and transaction id -> slot
    QHash<Key, CaptureExchange> timedOut;
    QHash<quint16, Framing> framings;
    std::vector<std::unique_ptr<ResponseVerdict>> verdicts(8);
    const auto verdictFor = [&](Framing framing) -> ResponseVerdict & {
        auto &v = verdicts[std::size_t(framing)];
        if (!v)
            v = std::make_unique<ResponseVerdict>(framing, false);
        return *v;
    };
    const auto framingOf = [&](quint16 link) { return framings.value(link, Framing::Tcp); };
    const auto emitReady = [&] {
        while (!queue.empty() && queue.front().done) {
            sink(queue.front().exchange);
            queue.pop_front();
            ++firstSlot;
        }
    };
    const auto push = [&](quint16 link) -> Slot & {
        Slot &s = queue.emplace_back();
        s.exchange.conversation = link;
        s.exchange.framing = framingOf(link);
        s.exchange.transaction.id = firstSlot + queue.size() - 1;
        return s;
    };
    const auto judge = [&](Transaction &t, Framing framing) {
        if (t.request.isEmpty() || t.response.isEmpty())
            return;
        ResponseVerdict::Result v = verdictFor(framing).judge(t.response, t.request);
        t.exceptionCode = v.exceptionCode;
        if (t.problem.isEmpty())
            t.problem = std::move(v.problem);
    };

    // Link names come as records the reader keeps to itself until it returns: a first pass that
    // only counts gives them, so that every exchange knows its framing as it is read.
    const TrafficJournalRecovery names = TrafficJournalReader::read(path, {});
    for (qsizetype i = 0; i < names.links.size(); ++i) {
        result.conversations.push_back(conversationFor(quint16(i), names.links.at(i)));
        framings.insert(quint16(i), result.conversations.back().framing);
        if (onConversation)
            onConversation(result.conversations.back());
    }

    // A server's journal (mbscope simulate, replay --serve) holds its requests In and its
    // answers Out: read as its clients saw them, so that one pairing serves both.
    TrafficMetadata metadata;
    QString metadataError;
    const bool server = !names.metadata.isEmpty() && TrafficMetadata::fromJson(names.metadata, &metadata, &metadataError)
                        && metadata.role == TrafficMetadata::Role::Server;

    result.recovery = TrafficJournalReader::read(path, [&](const TrafficEntry &entry) {
        TrafficEntry e = entry;
        if (server)
            e.direction = e.direction == TrafficDirection::In ? TrafficDirection::Out : TrafficDirection::In;
        const QByteArray bytes = e.bytes.toByteArray();
        if (e.verdict == TrafficVerdict::Garbage) {
            ++result.garbageFrames;
            return;
        }
        if (e.direction == TrafficDirection::Out) {
            if (e.transactionId == 0)
                return;
            const Key key{e.link, e.transactionId};
            const auto again = waiting.constFind(key);
            Slot *s = nullptr;
            if (again != waiting.cend()) {
                s = &queue[std::size_t(again.value() - firstSlot)]; // a retry: the last attempt counts
            } else {
                s = &push(e.link);
                waiting.insert(key, s->exchange.transaction.id);
            }
            s->exchange.requestPacket = e.sequence + 1;
            s->exchange.transaction.request = bytes;
            s->exchange.transaction.sentNs = wall(e.tNs);
            return;
        }
        const bool unsolicited = e.transactionId == 0 || e.verdict == TrafficVerdict::Unsolicited || e.verdict == TrafficVerdict::Sent;
        const Key key{e.link, e.transactionId};
        const auto pending = unsolicited ? waiting.end() : waiting.find(key);
        if (e.verdict == TrafficVerdict::Late || unsolicited || pending == waiting.end()) {
            Slot &s = push(e.link);
            Transaction &t = s.exchange.transaction;
            s.exchange.responsePacket = e.sequence + 1;
            t.response = bytes;
            t.firstByteNs = t.doneNs = wall(e.tNs);
            const auto before = timedOut.constFind(key);
            if (e.verdict == TrafficVerdict::Late && before != timedOut.cend()) {
                ++result.lateResponses;
                t.request = before->transaction.request;
                t.sentNs = before->transaction.sentNs;
                s.exchange.requestPacket = before->requestPacket;
                t.status = TransactionStatus::Late;
            } else {
                ++result.unmatchedResponses;
                s.exchange.kind = CaptureExchange::Kind::UnmatchedResponse;
                t.status = TransactionStatus::Unexpected;
                t.problem = unsolicited ? QStringLiteral("an answer when no request was waiting")
                                        : QStringLiteral("its request (transaction %1) is not in the journal").arg(e.transactionId);
            }
            s.done = true;
            emitReady();
            return;
        }
        Slot &s = queue[std::size_t(pending.value() - firstSlot)];
        waiting.erase(pending);
        Transaction &t = s.exchange.transaction;
        const int verdict = int(e.verdict);
        t.status = verdict <= int(TrafficVerdict::Late) ? TransactionStatus(verdict) : TransactionStatus::Unexpected;
        if (!bytes.isEmpty()) {
            s.exchange.responsePacket = e.sequence + 1;
            t.response = bytes;
            t.firstByteNs = t.doneNs = wall(e.tNs);
        }
        judge(t, s.exchange.framing);
        if (t.status == TransactionStatus::Timeout)
            timedOut.insert(key, s.exchange);
        s.done = true;
        emitReady();
    });

    for (Slot &s : queue) {
        if (!s.done) {
            ++result.noOutcome;
            s.exchange.transaction.status = TransactionStatus::Timeout;
            s.exchange.transaction.problem = QStringLiteral("the journal ends before this request's outcome");
            s.done = true;
        }
    }
    emitReady();
    return result;
}

} // namespace mbscope
