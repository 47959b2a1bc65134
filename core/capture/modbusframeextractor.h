#pragma once

#include "capture/capturedframe.h"
#include "capture/captureoptions.h"
#include "capture/capturepacket.h"
#include "capture/modbusportfinder.h"

#include <QtCore/QStringList>

#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

namespace mbscope {

struct DecodedPacket;

// Captured packets in, Modbus frames out, in capture order: each packet is taken apart
// (PacketDecoder); traffic to or from a Modbus port is sorted into conversations; each TCP
// direction is put back in order (TcpStreamReassembler) and cut into frames by the protocol's
// framer (MbapFramer, or RtuFramer with the direction known), each UDP datagram is one frame.
// After a hole in a stream (a packet the capture lost, found as soon as the peer acknowledges the
// bytes; a connection joined mid-way) the framer searches for the next frame boundary, so that
// only the frames the hole cut are lost. Whatever cannot be used is counted, and the first
// problems are kept with their packet numbers.
class ModbusFrameExtractor
{
public:
    using Sink = std::function<void(const CapturedFrame &)>;

    struct Counters {
        quint64 packets = 0;
        quint64 modbusPackets = 0;   // to or from a Modbus port
        quint64 otherPackets = 0;    // IP traffic on other ports, or not TCP/UDP
        quint64 notIp = 0;           // ARP and the like
        quint64 fragments = 0;       // IP fragments (not reassembled)
        quint64 malformedPackets = 0;
        quint64 unknownLinkType = 0;
        quint64 cutBySnapLength = 0; // Modbus packets whose payload the capture cut short
        quint64 frames = 0;
        qint64 retransmittedBytes = 0;
        qint64 lostBytes = 0;        // bytes the capture never saw (holes in TCP streams)
        quint64 gaps = 0;
        quint64 joinedMidStream = 0; // TCP directions whose start the capture missed
        qint64 skippedBytes = 0;     // bytes the framers could not frame
        quint64 skippedRuns = 0;
        qint64 cutByGapBytes = 0;    // of those: the rest of frames a gap cut, up to the next frame
    };
    static constexpr int kMaxProblems = 20;

    ModbusFrameExtractor(const CaptureOptions &options, Sink sink);
    ~ModbusFrameExtractor();
    ModbusFrameExtractor(const ModbusFrameExtractor &) = delete;
    ModbusFrameExtractor &operator=(const ModbusFrameExtractor &) = delete;

    // Called once per conversation when it is first seen, before any of its frames.
    void setConversationSink(std::function<void(const CaptureConversation &)> sink) { m_conversationSink = std::move(sink); }
    // Called for each gap (bytes a TCP stream lost), after the frames before it: the pairer must
    // not give an RTU answer after the gap to a request whose own answer the gap may have held.
    using GapSink = std::function<void(quint32 conversation, Direction direction)>;
    void setGapSink(GapSink sink) { m_gapSink = std::move(sink); }

    void add(const CapturePacket &packet);
    // The capture ended: streams waiting behind holes and unfinished frames are handed on.
    void finish();

    [[nodiscard]] const Counters &counters() const { return m_counters; }
    [[nodiscard]] std::vector<CaptureConversation> conversations() const;
    // "packet 12 (tcp 10.0.0.1:50000 -> 10.0.0.2:502): 3 bytes skipped (invalid MBAP header)"
    [[nodiscard]] const QStringList &problems() const { return m_problems; }
    [[nodiscard]] quint64 problemCount() const { return m_problemCount; }
    // TCP and UDP traffic on other ports that looks like Modbus (ModbusPortFinder).
    [[nodiscard]] std::vector<ModbusPortFinder::Found> otherModbusPorts() const { return m_portFinder.found(); }

private:
    struct Flow;
    struct FlowKey {
        IpAddress client;
        IpAddress server;
        quint16 clientPort = 0;
        quint16 serverPort = 0;
        bool udp = false;
        friend bool operator==(const FlowKey &, const FlowKey &) = default;
    };
    struct FlowKeyHash {
        std::size_t operator()(const FlowKey &key) const noexcept;
    };

    Flow &flowFor(const DecodedPacket &decoded, bool toServer, Framing framing);
    void onStreamBytes(Flow &flow, int direction, qint64 gap, QByteArrayView bytes);
    void collect(Flow &flow, int direction);
    void flushDirection(Flow &flow, int direction);
    void problem(quint64 packet, const Flow *flow, const QString &what);
    [[nodiscard]] bool isRtuPort(quint16 port) const;
    [[nodiscard]] bool isMbapPort(quint16 port) const;

    CaptureOptions m_options;
    Sink m_sink;
    std::function<void(const CaptureConversation &)> m_conversationSink;
    GapSink m_gapSink;
    Counters m_counters;
    std::vector<std::unique_ptr<Flow>> m_flows;
    std::unordered_map<FlowKey, std::size_t, FlowKeyHash> m_flowIndex;
    Flow *m_lastFlow = nullptr; // most packets belong to the flow of the one before
    FlowKey m_lastKey;
    qint64 m_timeNs = 0;
    quint64 m_packet = 0;
    QStringList m_problems;
    quint64 m_problemCount = 0;
    ModbusPortFinder m_portFinder;
};

} // namespace mbscope
