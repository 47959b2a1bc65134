#include "modbusframeextractor.h"

#include "capture/packetdecoder.h"
#include "capture/tcpstreamreassembler.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"

#include <QtCore/QHashFunctions>

namespace mbscope {

namespace {
constexpr quint8 kFin = 0x01;
constexpr quint8 kSyn = 0x02;
constexpr quint8 kRst = 0x04;
constexpr quint8 kAck = 0x10;
constexpr int kToServer = 0;
constexpr int kToClient = 1;
} // namespace

struct ModbusFrameExtractor::Flow {
    CaptureConversation info;
    std::unique_ptr<StreamFramer> framers[2];
    std::unique_ptr<TcpStreamReassembler> streams[2];
    qint64 lastFeedNs[2]{};
    quint64 lastPacket[2]{};
    // What the framers cut, swapped out of them (StreamFramer::takeOutput): no list per frame.
    QList<StreamFrame> frames[2];
    QList<SkippedBytes> skipped[2];
};

std::size_t ModbusFrameExtractor::FlowKeyHash::operator()(const FlowKey &key) const noexcept
{
    std::size_t seed = qHashBits(key.client.bytes.data(), key.client.bytes.size());
    seed = qHashMulti(seed, qHashBits(key.server.bytes.data(), key.server.bytes.size()), key.clientPort, key.serverPort, key.udp);
    return seed;
}

ModbusFrameExtractor::ModbusFrameExtractor(const CaptureOptions &options, Sink sink)
    : m_options(options), m_sink(std::move(sink))
{
}

ModbusFrameExtractor::~ModbusFrameExtractor() = default;

bool ModbusFrameExtractor::isRtuPort(quint16 port) const
{
    return m_options.rtuPorts.contains(port);
}

bool ModbusFrameExtractor::isMbapPort(quint16 port) const
{
    return m_options.mbapPorts.contains(port);
}

std::vector<CaptureConversation> ModbusFrameExtractor::conversations() const
{
    std::vector<CaptureConversation> list;
    list.reserve(m_flows.size());
    for (const auto &flow : m_flows)
        list.push_back(flow->info);
    return list;
}

void ModbusFrameExtractor::problem(quint64 packet, const Flow *flow, const QString &what)
{
    ++m_problemCount;
    if (m_problems.size() >= kMaxProblems)
        return;
    m_problems.append(flow ? QStringLiteral("packet %1 (%2): %3").arg(packet).arg(flow->info.description(), what)
                           : QStringLiteral("packet %1: %2").arg(packet).arg(what));
}

ModbusFrameExtractor::Flow &ModbusFrameExtractor::flowFor(const DecodedPacket &d, bool toServer, Framing framing)
{
    FlowKey key;
    key.udp = d.outcome == DecodedPacket::Outcome::Udp;
    key.client = toServer ? d.source : d.destination;
    key.server = toServer ? d.destination : d.source;
    key.clientPort = toServer ? d.sourcePort : d.destinationPort;
    key.serverPort = toServer ? d.destinationPort : d.sourcePort;
    if (m_lastFlow && key == m_lastKey)
        return *m_lastFlow;
    auto [it, inserted] = m_flowIndex.try_emplace(key, m_flows.size());
    if (inserted) {
        auto flow = std::make_unique<Flow>();
        flow->info.id = quint32(m_flows.size());
        flow->info.udp = key.udp;
        flow->info.client = key.client;
        flow->info.server = key.server;
        flow->info.clientPort = key.clientPort;
        flow->info.serverPort = key.serverPort;
        flow->info.framing = framing;
        for (int direction : {kToServer, kToClient}) {
            if (framing == Framing::Rtu)
                flow->framers[direction] = std::make_unique<RtuFramer>(direction == kToServer ? Direction::Request : Direction::Response);
            else
                flow->framers[direction] = std::make_unique<MbapFramer>();
            if (!key.udp) {
                Flow *raw = flow.get();
                flow->streams[direction] = std::make_unique<TcpStreamReassembler>(
                    [this, raw, direction](qint64 gap, QByteArrayView bytes) { onStreamBytes(*raw, direction, gap, bytes); });
            }
        }
        m_flows.push_back(std::move(flow));
        if (m_conversationSink)
            m_conversationSink(m_flows.back()->info);
    }
    m_lastKey = key;
    m_lastFlow = m_flows[it->second].get();
    return *m_lastFlow;
}

void ModbusFrameExtractor::add(const CapturePacket &packet)
{
    ++m_counters.packets;
    m_timeNs = packet.timeNs;
    m_packet = packet.number;
    const DecodedPacket d = PacketDecoder::decode(packet);
    switch (d.outcome) {
    case DecodedPacket::Outcome::NotIp:
        ++m_counters.notIp;
        return;
    case DecodedPacket::Outcome::OtherProtocol:
        ++m_counters.otherPackets;
        return;
    case DecodedPacket::Outcome::Fragment:
        ++m_counters.fragments;
        return;
    case DecodedPacket::Outcome::Malformed:
        ++m_counters.malformedPackets;
        problem(packet.number, nullptr, QString::fromLatin1(d.problem));
        return;
    case DecodedPacket::Outcome::UnknownLinkType:
        if (m_counters.unknownLinkType++ == 0)
            problem(packet.number, nullptr, QStringLiteral("link type %1 is not one mbscope reads (Ethernet, Linux cooked, "
                                                           "loopback, raw IP): its packets are skipped")
                                                .arg(packet.linkType));
        return;
    case DecodedPacket::Outcome::Tcp:
    case DecodedPacket::Outcome::Udp:
        break;
    }
    bool toServer = false;
    if (isRtuPort(d.destinationPort) || isMbapPort(d.destinationPort)) {
        toServer = true;
    } else if (!isRtuPort(d.sourcePort) && !isMbapPort(d.sourcePort)) {
        ++m_counters.otherPackets;
        m_portFinder.add(d);
        return;
    }
    const quint16 serverPort = toServer ? d.destinationPort : d.sourcePort;
    const bool udp = d.outcome == DecodedPacket::Outcome::Udp;
    const Framing framing = isRtuPort(serverPort) ? Framing::Rtu : udp ? Framing::Udp : Framing::Tcp;
    ++m_counters.modbusPackets;
    Flow &flow = flowFor(d, toServer, framing);
    const int direction = toServer ? kToServer : kToClient;
    if (d.truncated) {
        ++m_counters.cutBySnapLength;
        problem(packet.number, &flow, QStringLiteral("the capture kept %1 of its %2 payload bytes (snap length): the rest is lost")
                                          .arg(d.payload.size()).arg(d.payloadLength));
    }
    if (udp) {
        if (d.payload.isEmpty())
            return;
        CapturedFrame frame;
        frame.timeNs = m_timeNs;
        frame.packet = m_packet;
        frame.conversation = flow.info.id;
        frame.framing = framing;
        frame.direction = toServer ? Direction::Request : Direction::Response;
        frame.bytes = d.payload.toByteArray();
        ++(toServer ? flow.info.requests : flow.info.responses);
        ++m_counters.frames;
        m_sink(frame);
        return;
    }
    const quint8 flags = d.tcpFlags;
    if ((flags & kSyn) && !(flags & kAck) && flow.streams[kToServer]->delivered() > 0) {
        // A new connection from the same client port: the old one ended unseen.
        for (int dir : {kToServer, kToClient}) {
            flow.streams[dir]->finish();
            flushDirection(flow, dir);
            flow.streams[dir]->reset();
            flow.framers[dir]->reset();
        }
    }
    // The peer has every byte it acknowledges: a hole before them will never be filled.
    if (flags & kAck)
        flow.streams[1 - direction]->acknowledged(d.acknowledgement);
    const int other = 1 - direction;
    if (!d.payload.isEmpty() && framing == Framing::Rtu) {
        // RTU has no length for every code: a pause, or the other side speaking, ends a frame.
        if (flow.framers[other]->pendingSize() > 0)
            flushDirection(flow, other);
        if (flow.framers[direction]->pendingSize() > 0 && m_timeNs - flow.lastFeedNs[direction] > m_options.rtuSilenceNs)
            flushDirection(flow, direction);
    } else if (!d.payload.isEmpty() && flow.framers[other]->isSearching() && flow.framers[other]->pendingSize() > 0) {
        // After a gap, a frame waiting for the next header to confirm it is confirmed by the
        // other side speaking: Modbus answers a whole request, and a client reads a whole answer.
        flushDirection(flow, other);
    }
    flow.streams[direction]->add(d.sequence, flags, d.payload);
    if (flags & (kFin | kRst)) {
        flow.streams[direction]->finish();
        flushDirection(flow, direction);
        if (flags & kRst) {
            flow.streams[1 - direction]->finish();
            flushDirection(flow, 1 - direction);
        }
    }
}

void ModbusFrameExtractor::onStreamBytes(Flow &flow, int direction, qint64 gap, QByteArrayView bytes)
{
    StreamFramer &framer = *flow.framers[direction];
    const QString towards = direction == kToServer ? QStringLiteral("to the server") : QStringLiteral("to the client");
    if (gap == TcpStreamReassembler::kJoinedMidStream) {
        ++m_counters.joinedMidStream;
        flow.info.joinedMidStream = true;
        problem(m_packet, &flow, QStringLiteral("the capture began after the connection did: the bytes %1 are framed from "
                                                "the first frame boundary found")
                                     .arg(towards));
        framer.restartAfterGap();
    } else if (gap > 0) {
        ++m_counters.gaps;
        m_counters.lostBytes += gap;
        ++(direction == kToServer ? flow.info.requestGaps : flow.info.responseGaps);
        (direction == kToServer ? flow.info.requestBytesLost : flow.info.responseBytesLost) += gap;
        problem(m_packet, &flow, QStringLiteral("%1 byte(s) %2 never captured (a packet the capture lost): framing "
                                                "starts again at the next frame boundary")
                                     .arg(gap)
                                     .arg(towards));
        if (framer.isSearching()) {
            // A frame waiting for the next header to confirm it is confirmed by the gap as by
            // a silence.
            flushDirection(flow, direction);
        } else {
            // The start of a frame the gap cut: not a frame, nor a device's fault.
            collect(flow, direction);
            m_counters.skippedBytes += framer.pendingSize();
            m_counters.cutByGapBytes += framer.pendingSize();
        }
        framer.restartAfterGap();
        if (m_gapSink)
            m_gapSink(flow.info.id, direction == kToServer ? Direction::Request : Direction::Response);
    }
    framer.feed(bytes, m_timeNs);
    flow.lastFeedNs[direction] = m_timeNs;
    flow.lastPacket[direction] = m_packet;
    collect(flow, direction);
}

void ModbusFrameExtractor::flushDirection(Flow &flow, int direction)
{
    flow.framers[direction]->flushOnSilence();
    collect(flow, direction);
}

void ModbusFrameExtractor::collect(Flow &flow, int direction)
{
    StreamFramer &framer = *flow.framers[direction];
    QList<StreamFrame> &frames = flow.frames[direction];
    QList<SkippedBytes> &skipped = flow.skipped[direction];
    if (!framer.takeOutput(frames, skipped))
        return;
    const auto emitFrame = [&](const QByteArray &bytes, qint64 timeNs, FrameStatus status, bool undelimited) {
        CapturedFrame frame;
        frame.timeNs = timeNs;
        frame.packet = flow.lastPacket[direction];
        frame.conversation = flow.info.id;
        frame.framing = flow.info.framing;
        frame.direction = direction == kToServer ? Direction::Request : Direction::Response;
        frame.status = status;
        frame.undelimited = undelimited;
        frame.bytes = bytes;
        if (!undelimited) {
            ++(direction == kToServer ? flow.info.requests : flow.info.responses);
            ++m_counters.frames;
        }
        m_sink(frame);
    };
    // Frames and skipped runs in stream order, as the bytes came (the engine's order too).
    qsizetype f = 0;
    qsizetype k = 0;
    while (f < frames.size() || k < skipped.size()) {
        if (k < skipped.size() && (f >= frames.size() || skipped.at(k).offset < frames.at(f).offset)) {
            const SkippedBytes &s = skipped.at(k++);
            m_counters.skippedBytes += s.count();
            ++m_counters.skippedRuns;
            if (s.reason == SkipReason::AfterGap)
                m_counters.cutByGapBytes += s.count();
            problem(flow.lastPacket[direction], &flow, QStringLiteral("%1 byte(s) skipped (%2): %3")
                                                           .arg(s.count())
                                                           .arg(QLatin1String(skipReasonName(s.reason)),
                                                                QString::fromLatin1(s.bytes.left(16).toHex(' ').toUpper()) +
                                                                    (s.count() > 16 ? QStringLiteral(" ...") : QString())));
            // An RTU answer with a wrong CRC, or cut short, cannot be delimited by the framer;
            // its unit and function code may still name the waiting request (as in the engine).
            if (flow.info.framing == Framing::Rtu && direction == kToClient && s.count() >= 4
                && (s.reason == SkipReason::ChecksumMismatch || s.reason == SkipReason::Incomplete))
                emitFrame(s.bytes, flow.lastFeedNs[direction], FrameStatus::Malformed, true);
            continue;
        }
        const StreamFrame &frame = frames.at(f++);
        emitFrame(frame.bytes, frame.lastByteNs, frame.status, false);
    }
}

void ModbusFrameExtractor::finish()
{
    for (const auto &flow : m_flows) {
        for (int direction : {kToServer, kToClient}) {
            if (flow->streams[direction])
                flow->streams[direction]->finish();
            flushDirection(*flow, direction);
        }
    }
    m_counters.retransmittedBytes = 0;
    for (const auto &flow : m_flows) {
        for (const auto &stream : flow->streams) {
            if (stream)
                m_counters.retransmittedBytes += stream->retransmittedBytes();
        }
    }
}

} // namespace mbscope
