#pragma once

#include "capture/captureexchange.h"
#include "capture/capturedframe.h"
#include "capture/capturefilewriter.h"
#include "capture/packetsynthesizer.h"

#include <QtCore/QList>
#include <QtCore/QStringList>

#include <map>
#include <vector>

namespace mbscope {

// Exchanges back into packets that Wireshark decodes as Modbus: each conversation becomes one
// TCP connection (a handshake, then every request from the client and every answer from the
// server as one segment, sequence and acknowledgement numbers running on) or UDP datagrams,
// between the conversation's addresses and ports. Requests are stamped with their sentNs,
// answers with their doneNs, and packets are written in time order (exchanges come in request
// order, so a packet is written once no later request can come before it).
//
// MBAP goes to its port (502 by default: tshark decodes it as Modbus/TCP by itself). RTU frames
// go to the conversation's port, which tshark does not know: decodeOptions() gives the option
// to tell it ("-o mbrtu.tcp.port:4001"). ASCII frames are written as they are; tshark has no
// dissector for ASCII over TCP.
//
// A serial line's conversation (a journal of an rtu:// link, CaptureConversation::serialPort)
// has no addresses to invent: in pcapng it is an interface of its own named after the port
// (if_name "/dev/ttyUSB0", if_description "Modbus RTU on serial port /dev/ttyUSB0"), link type
// RTAC serial (LINKTYPE_RTAC_SERIAL, 250), each frame as the line carried it behind the link
// type's 12-byte header (time, event 1 DATA_TX_START for the master's requests, 2 DATA_RX_START
// for the answers). Wireshark decodes the bytes as Modbus RTU with Decode As (tshark -d
// rtacser.data,mbrtu, Wireshark 4.0). A pcap file has one link type and no interface names: there
// a serial line's frames go as RTU over TCP between stand-in addresses, port 4001, and
// decodeOptions() says so.
class ExchangePcapExporter
{
public:
    explicit ExchangePcapExporter(CaptureFileWriter &writer) : m_writer(writer) {}

    // The addresses and ports of a conversation, before its first exchange (one never described
    // gets 10.0.0.1 -> 10.0.0.2 and its framing's usual port).
    void addConversation(const CaptureConversation &conversation);
    void add(const CaptureExchange &exchange);
    void finish(); // writes what is still held back

    [[nodiscard]] QList<quint16> rtuPorts() const { return m_rtuPorts; }
    // What tshark needs to decode every conversation written, one entry per port it does not
    // know by itself: "port 4001 (RTU over TCP): -o mbrtu.tcp.port:4001", "serial port
    // /dev/ttyUSB0 (Modbus RTU): -d rtacser.data,mbrtu". MBAP on 502 needs none. Also which
    // addresses are stand-ins (a journal that does not say its client).
    [[nodiscard]] QStringList decodeOptions() const { return m_decodeOptions; }
    [[nodiscard]] quint64 packets() const { return m_writer.packets(); }

private:
    struct Stream {
        CaptureConversation info;
        PacketSynthesizer::Endpoints endpoints;
        bool known = false;
        bool opened = false;
        int serialInterface = -1; // a serial line's, in pcapng
        quint32 clientNext = 0x10000000; // next sequence number from the client
        quint32 serverNext = 0x20000000;
    };
    struct Held {
        quint32 conversation = 0;
        bool toServer = true;
        QByteArray payload;
    };

    Stream &stream(quint32 conversation, Framing framing);
    void hold(qint64 timeNs, quint32 conversation, bool toServer, const QByteArray &payload);
    void writeUpTo(qint64 timeNs);
    void writeOne(qint64 timeNs, const Held &held);

    CaptureFileWriter &m_writer;
    std::vector<Stream> m_streams;
    std::multimap<qint64, Held> m_held;
    QList<quint16> m_rtuPorts;
    QStringList m_decodeOptions;
};

} // namespace mbscope
