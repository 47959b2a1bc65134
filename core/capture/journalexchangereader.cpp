#include "journalexchangereader.h"

#include <QtCore/qnumeric.h>

#include <algorithm>

#include "exchange/responseverdict.h"
#include "protocol/pdusize.h"
#include "traffic/journalendpoints.h"
#include "traffic/trafficmetadata.h"
#include "transport/linkurl.h"

#include <QtCore/QFile>
#include <QtCore/QHash>
#include <QtNetwork/QHostAddress>
#include <QtCore/QtEndian>

#include <deque>
#include <vector>
#include <memory>
#include <utility>

namespace mbscope {

namespace {

struct Slot {
    CaptureExchange exchange;
    bool done = false;
};

// "192.168.1.5:40312" or "[::1]:502" into an address and a port; false when it is neither.
bool parseEndpoint(const QString &text, IpAddress *address, quint16 *port)
{
    const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0)
        return false;
    bool portOk = false;
    const uint number = text.mid(colon + 1).toUInt(&portOk);
    QString host = text.left(colon);
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    QHostAddress parsed;
    if (!portOk || number > 0xFFFF || !parsed.setAddress(host))
        return false;
    bool v4 = false;
    const quint32 ipv4 = parsed.toIPv4Address(&v4);
    IpAddress a;
    if (v4) {
        a.bytes = {quint8(ipv4 >> 24), quint8(ipv4 >> 16), quint8(ipv4 >> 8), quint8(ipv4)};
    } else {
        const Q_IPV6ADDR ipv6 = parsed.toIPv6Address();
        for (int i = 0; i < 16; ++i)
            a.bytes[std::size_t(i)] = ipv6[i];
        a.v6 = true;
    }
    *address = a;
    *port = quint16(number);
    return true;
}

// What a link's name (its URL) says of its conversation. Serial: the port. Network: the server
// when the URL names it by address; the client is not in the URL (an endpoints note gives it).
// Ends not known get stand-in addresses, which only a pcap export's packets carry:
// 10.0.0.1:(49152 + link) -> 10.0.0.2:(the URL's port).
CaptureConversation conversationFor(quint16 link, const QString &name)
{
    CaptureConversation c;
    c.id = link;
    c.client.bytes = {10, 0, 0, 1};
    c.clientPort = quint16(49152 + link);
    c.clientKnown = false;
    c.server.bytes = {10, 0, 0, 2};
    c.serverPort = 502;
    c.serverKnown = false;
    c.serverName = name;
    const LinkUrl::Result parsed = LinkUrl::parse(name);
    if (!parsed.url)
        return c;
    const LinkUrl &url = *parsed.url;
    c.framing = url.framing();
    c.udp = url.isDatagram();
    if (url.isSerial()) {
        c.serialPort = url.serial.device;
        c.serverPort = 4001; // only for a pcap file, which cannot name a serial port
        return c;
    }
    c.serverPort = url.port;
    const QString host = url.host.contains(QLatin1Char(':')) ? QLatin1Char('[') + url.host + QLatin1Char(']') : url.host;
    c.serverName = host + QLatin1Char(':') + QString::number(url.port);
    quint16 port = 0;
    c.serverKnown = parseEndpoint(c.serverName, &c.server, &port);
    return c;
}


// Where the answer that starts bytes ends, by its framing's own rule: what a client's framer
// (linkframing.h) goes by to join the pieces of an answer. MBAP: the header's length; RTU: the
// length the function code and byte count predict (pdusize), and the CRC; ASCII: CR LF.
// > 0: the frame's size (more than bytes.size() when pieces are still to come); 0: too few bytes
// to tell yet; -1: the bytes say nothing of their end (no length rule, not a header): they are
// taken as they are.
qsizetype answerSize(QByteArrayView bytes, Framing framing)
{
    switch (framing) {
    case Framing::Tcp:
    case Framing::Udp: {
        if (bytes.size() < 6)
            return 0;
        const int length = qFromBigEndian<quint16>(bytes.data() + 4);
        const quint16 protocol = qFromBigEndian<quint16>(bytes.data() + 2);
        return protocol == 0 && length >= 2 && length <= 254 ? 6 + length : -1;
    }
    case Framing::Rtu: {
        if (bytes.size() < 2)
            return 0;
        const pdusize::Expected e = pdusize::expectedPduSize(bytes.sliced(1), Direction::Response);
        if (e.status == pdusize::Status::Complete)
            return 1 + e.size + 2;
        return e.status == pdusize::Status::NeedMore ? 0 : -1;
    }
    case Framing::Ascii: {
        if (bytes.isEmpty())
            return 0;
        if (bytes.front() != ':')
            return -1;
        const qsizetype end = QByteArrayView(bytes).indexOf("\r\n");
        return end < 0 ? 0 : end + 2;
    }
    default:
        return -1;
    }
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
    const auto judge = [&](Transaction &t, Framing framing) {
        if (t.request.isEmpty() || t.response.isEmpty())
            return;
        ResponseVerdict::Result v = verdictFor(framing).judge(t.response, t.request);
        t.exceptionCode = v.exceptionCode;
        // The journal's verdict is what its writer made of the answer: the engine judged it as
        // this does, but a server journal (simulate) says what it sent, a CRC its fault rule
        // damaged included, as sent ("ok"). An answer is judged here by the check every other
        // path uses (ResponseVerdict, as captures and the engine): what it finds wrong in the
        // bytes stands whatever the journal says; what the writer found that the bytes alone do
        // not show (an answer the line cut short) stays.
        const bool answered = t.status == TransactionStatus::Ok || t.status == TransactionStatus::Exception;
        if (answered && v.status != TransactionStatus::Ok && v.status != TransactionStatus::Exception) {
            t.status = v.status;
            t.problem = std::move(v.problem);
            return;
        }
        if (answered)
            t.status = v.status;
        if (t.problem.isEmpty())
            t.problem = std::move(v.problem);
    };

    // Link names come as records the reader keeps to itself until it returns: a first pass that
    // only counts gives them, so that every exchange knows its framing as it is read.
    const TrafficJournalRecovery names = TrafficJournalReader::read(path, {});
    for (qsizetype i = 0; i < names.links.size(); ++i) {
        result.conversations.push_back(conversationFor(quint16(i), names.links.at(i)));
        framings.insert(quint16(i), result.conversations.back().framing);
    }
    // A link's conversation changes where an endpoints note says another connection carries it
    // (a reconnect, another client of the simulator): each connection is a conversation of its
    // own, announced (onConversation) just before its first exchange.
    QHash<quint16, quint32> current; // link -> its conversation now
    std::vector<bool> announced(result.conversations.size(), false);
    const auto conversationOf = [&](quint16 link) -> quint32 {
        quint32 id = link;
        if (const auto it = current.constFind(link); it != current.cend()) {
            id = it.value();
        } else if (link >= names.links.size()) { // a link id never named (a damaged journal)
            id = quint32(result.conversations.size());
            result.conversations.push_back(conversationFor(link, QString()));
            result.conversations.back().id = id;
            announced.push_back(false);
            current.insert(link, id);
        }
        if (!announced[id]) {
            announced[id] = true;
            if (onConversation)
                onConversation(result.conversations[id]);
        }
        return id;
    };
    const auto onNote = [&](const TrafficJournalNote &note) {
        const std::optional<JournalEndpoints> endpoints = JournalEndpoints::fromJson(note.json);
        if (!endpoints || note.link >= names.links.size())
            return;
        CaptureConversation c = result.conversations[note.link]; // the link's own: framing, URL
        c.clientKnown = parseEndpoint(endpoints->client, &c.client, &c.clientPort);
        if (parseEndpoint(endpoints->server, &c.server, &c.serverPort))
            c.serverKnown = true;
        const quint32 now = current.value(note.link, note.link);
        const CaptureConversation &was = result.conversations[now];
        if (was.clientKnown == c.clientKnown && was.client == c.client && was.clientPort == c.clientPort && was.server == c.server
            && was.serverPort == c.serverPort)
            return; // the same connection
        if (!announced[now]) {
            c.id = now; // nothing went over the one it replaces
            result.conversations[now] = c;
            return;
        }
        c.id = quint32(result.conversations.size());
        result.conversations.push_back(c);
        announced.push_back(false);
        current.insert(note.link, c.id);
    };
    // A server's journal (mbscope simulate, replay --serve) holds its requests In and its
    // answers Out: read as its clients saw them, so that one pairing serves both.
    TrafficMetadata metadata;
    QString metadataError;
    const bool serverJournal = !names.metadata.isEmpty() && TrafficMetadata::fromJson(names.metadata, &metadata, &metadataError)
                               && metadata.role == TrafficMetadata::Role::Server;
    // Which links are the server's: every one, unless the metadata names where it listened and
    // the journal holds other links too (the inline tap's: its device leg, recorded by an engine
    // as a client records, requests out and answers in).
    QList<bool> servedLinks;
    for (qsizetype i = 0; i < names.links.size(); ++i)
        servedLinks.append(serverJournal && (metadata.listen.isEmpty() || metadata.listen.contains(names.links.at(i))));
    const auto served = [&servedLinks](quint16 link) { return link < servedLinks.size() && servedLinks.at(link); };

    const auto push = [&](quint16 link) -> Slot & {
        Slot &s = queue.emplace_back();
        s.exchange.conversation = conversationOf(link);
        s.exchange.framing = framingOf(link);
        s.exchange.recordedAs = served(link) ? CaptureExchange::RecordedAs::Server : CaptureExchange::RecordedAs::Client;
        s.exchange.transaction.id = firstSlot + queue.size() - 1;
        return s;
    };


    // A server writes an answer as it leaves, and a fault rule may send it in pieces (chunks,
    // trickle: FaultPlan's ResponseChunks, each written after its delay) or twice (duplicate):
    // its journal holds each piece as a frame of its own, with the time it left and the
    // request's id (Simulator::setTrafficLog). The journal is left as the wire was, piece by
    // piece with their times (a pcap export of it shows the pieces' timing only through these),
    // and the pieces are joined here into what the client's framer made of them: a whole answer
    // when its framing's length rule says it is complete (answerSize), stamped from its first
    // piece to its last (the latency runs to the last byte, as the engine's); bytes beyond it
    // start the next answer to the same request, a duplicate, which is what the engine calls it
    // (an answer matching no request, not a malformed first one). Pieces still short of a whole
    // answer when another answer starts on the same connection, or when the journal ends, are
    // the answer as the client got it, cut short. Datagram and delimited links are left alone:
    // a datagram is a frame of its own to the client.
    struct Pieces {
        QByteArray bytes;
        qint64 firstNs = 0;  // monotonic, of the piece that holds the first byte
        qint64 lastNs = 0;   // of the last piece
        quint64 sequence = 0; // of the first piece
        TrafficVerdict verdict = TrafficVerdict::Ok;
        quint32 conversation = 0;
    };
    struct Answered {
        quint32 conversation = 0;
        quint64 requestPacket = 0;
    };
    QHash<Key, Pieces> pieces;
    QHash<quint32, Key> openPieces; // conversation -> the answer whose pieces are coming
    // The last answered requests, for the duplicates that follow their answers (bounded: a
    // duplicate comes after its answer, not thousands of answers later).
    constexpr qsizetype kAnsweredKept = 1024;
    QHash<Key, Answered> answered;
    std::deque<Key> answeredOrder;
    QHash<quint16, bool> joinable;
    for (qsizetype i = 0; i < names.links.size(); ++i) {
        const LinkUrl::Result parsed = LinkUrl::parse(names.links.at(i));
        joinable.insert(quint16(i), served(quint16(i)) && parsed.url && !parsed.url->isDatagram() && !parsed.url->delimited.enabled);
    }

    // An answer (the whole of one, or what there is of it) with the id of its request.
    const auto answerFrame = [&](quint16 link, quint64 transactionId, TrafficVerdict verdictIn, const QByteArray &bytes,
                                 qint64 firstNs, qint64 lastNs, quint64 sequence) {
        const bool unsolicited = transactionId == 0 || verdictIn == TrafficVerdict::Unsolicited || verdictIn == TrafficVerdict::Sent;
        const Key key{link, transactionId};
        const auto pending = unsolicited ? waiting.end() : waiting.find(key);
        if (verdictIn == TrafficVerdict::Late || unsolicited || pending == waiting.end()) {
            Slot &s = push(link);
            Transaction &t = s.exchange.transaction;
            s.exchange.responsePacket = sequence + 1;
            t.response = bytes;
            t.firstByteNs = wall(firstNs);
            t.doneNs = wall(lastNs);
            const auto before = timedOut.constFind(key);
            const auto again = unsolicited ? answered.cend() : answered.constFind(key);
            if (verdictIn == TrafficVerdict::Late && before != timedOut.cend()) {
                ++result.lateResponses;
                t.request = before->transaction.request;
                t.sentNs = before->transaction.sentNs;
                s.exchange.requestPacket = before->requestPacket;
                t.status = TransactionStatus::Late;
            } else {
                ++result.unmatchedResponses;
                s.exchange.kind = CaptureExchange::Kind::UnmatchedResponse;
                t.status = TransactionStatus::Unexpected;
                if (again != answered.cend()) {
                    ++result.duplicateResponses;
                    t.problem = QStringLiteral("a duplicate: another answer to transaction %1 (frame %2), answered already")
                                    .arg(transactionId)
                                    .arg(again->requestPacket);
                } else {
                    t.problem = unsolicited ? QStringLiteral("an answer when no request was waiting")
                                            : QStringLiteral("its request (transaction %1) is not in the journal").arg(transactionId);
                }
            }
            s.done = true;
            emitReady();
            return;
        }
        Slot &s = queue[std::size_t(pending.value() - firstSlot)];
        waiting.erase(pending);
        Transaction &t = s.exchange.transaction;
        const int verdict = int(verdictIn);
        t.status = verdict <= int(TrafficVerdict::Late) ? TransactionStatus(verdict) : TransactionStatus::Unexpected;
        if (!bytes.isEmpty()) {
            s.exchange.responsePacket = sequence + 1;
            t.response = bytes;
            t.firstByteNs = wall(firstNs);
            t.doneNs = wall(lastNs);
            if (served(key.first) && !answered.contains(key)) {
                answered.insert(key, Answered{s.exchange.conversation, s.exchange.requestPacket});
                answeredOrder.push_back(key);
                if (answeredOrder.size() > kAnsweredKept) {
                    answered.remove(answeredOrder.front());
                    answeredOrder.pop_front();
                }
            }
        }
        judge(t, s.exchange.framing);
        if (t.status == TransactionStatus::Timeout)
            timedOut.insert(key, s.exchange);
        s.done = true;
        emitReady();
    };
    // The pieces of an answer that will get no more: the answer as its client got it.
    const auto flushPieces = [&](const Key &key) {
        const auto it = pieces.find(key);
        if (it == pieces.end())
            return;
        const Pieces p = it.value();
        pieces.erase(it);
        if (const auto open = openPieces.constFind(p.conversation); open != openPieces.cend() && open.value() == key)
            openPieces.erase(open);
        if (!p.bytes.isEmpty())
            answerFrame(key.first, key.second, p.verdict, p.bytes, p.firstNs, p.lastNs, p.sequence);
    };
    // One piece of a server's answer: true when taken (joined with the others of its answer).
    const auto answerPiece = [&](const TrafficEntry &e, const QByteArray &bytes) -> bool {
        if (!joinable.value(e.link, false) || e.transactionId == 0 || bytes.isEmpty()
            || (e.verdict != TrafficVerdict::Ok && e.verdict != TrafficVerdict::Exception))
            return false;
        const Key key{e.link, e.transactionId};
        auto it = pieces.find(key);
        if (it == pieces.end()) {
            quint32 conversation = 0;
            if (const auto w = waiting.constFind(key); w != waiting.cend())
                conversation = queue[std::size_t(w.value() - firstSlot)].exchange.conversation;
            else if (const auto a = answered.constFind(key); a != answered.cend())
                conversation = a->conversation;
            else
                return false; // no request of the journal's: an answer matching none, as it is
            Pieces fresh;
            fresh.conversation = conversation;
            it = pieces.insert(key, fresh);
        }
        const quint32 conversation = it->conversation;
        // Answers go out one after the other on a connection: one starting ends the one before.
        if (const auto open = openPieces.constFind(conversation); open != openPieces.cend() && open.value() != key) {
            flushPieces(open.value());
            it = pieces.find(key);
        }
        Pieces &p = it.value();
        if (p.bytes.isEmpty()) {
            p.firstNs = e.tNs;
            p.sequence = e.sequence;
            p.verdict = e.verdict;
        }
        p.bytes += bytes;
        p.lastNs = e.tNs;
        openPieces.insert(conversation, key);
        const Framing framing = framingOf(e.link);
        while (!p.bytes.isEmpty()) {
            const qsizetype size = answerSize(p.bytes, framing);
            if (size == 0 || size > p.bytes.size())
                return true; // more pieces to come
            const qsizetype take = size < 0 ? p.bytes.size() : size;
            const QByteArray whole = p.bytes.left(take);
            const qint64 firstNs = p.firstNs;
            const quint64 sequence = p.sequence;
            const TrafficVerdict verdict = p.verdict;
            p.bytes.remove(0, take);
            p.firstNs = e.tNs;
            p.sequence = e.sequence;
            answerFrame(e.link, e.transactionId, verdict, whole, firstNs, e.tNs, sequence);
        }
        pieces.remove(key);
        openPieces.remove(conversation);
        return true;
    };

    result.recovery = TrafficJournalReader::read(path, [&](const TrafficEntry &entry) {
        TrafficEntry e = entry;
        if (served(e.link))
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
        if (served(e.link) && answerPiece(e, bytes))
            return;
        answerFrame(e.link, e.transactionId, e.verdict, bytes, e.tNs, e.tNs, e.sequence);
    }, onNote);

    // The journal ends: pieces still short of an answer are all their client got.
    std::vector<std::pair<quint64, Key>> left;
    for (auto it = pieces.cbegin(); it != pieces.cend(); ++it)
        left.emplace_back(it->sequence, it.key());
    std::sort(left.begin(), left.end());
    for (const auto &[sequence, key] : left)
        flushPieces(key);

    for (Slot &s : queue) {
        if (!s.done) {
            // Cut by the end of the journal (its writer killed with the request in flight): no
            // outcome to count, so not a timeout.
            ++result.noOutcome;
            s.exchange.kind = CaptureExchange::Kind::Unanswered;
            s.exchange.transaction.status = TransactionStatus::Timeout;
            s.exchange.transaction.problem = QStringLiteral("unanswered at the end of the recording: the journal ends before this request's outcome");
            s.done = true;
        }
    }
    emitReady();
    return result;
}

} // namespace mbscope
