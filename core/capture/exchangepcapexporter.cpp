#include "exchangepcapexporter.h"
#include "protocol/framingtraits.h"

#include <QtCore/QtEndian>

#include <algorithm>
#include <limits>

namespace mbscope {

void ExchangePcapExporter::addConversation(const CaptureConversation &c)
{
    if (m_streams.size() <= c.id)
        m_streams.resize(c.id + 1);
    Stream &s = m_streams[c.id];
    if (s.known)
        return;
    s.info = c;
    s.known = true;
}

ExchangePcapExporter::Stream &ExchangePcapExporter::stream(quint32 conversation, Framing framing)
{
    if (m_streams.size() <= conversation)
        m_streams.resize(conversation + 1);
    Stream &s = m_streams[conversation];
    if (!s.known) {
        // A conversation nobody described: made-up addresses, the framing's usual port.
        s.info.id = conversation;
        s.info.framing = framing;
        s.info.udp = framing == Framing::Udp;
        s.info.client.bytes = {10, 0, 0, 1};
        s.info.server.bytes = {10, 0, 0, 2};
        s.info.clientPort = quint16(49152 + conversation);
        s.info.serverPort = isSerialLine(framing) ? 4001 : 502;
        s.known = true;
    }
    if (s.endpoints.serverPort == 0) {
        s.endpoints = {s.info.client, s.info.server, s.info.clientPort, s.info.serverPort};
        if (s.info.isSerial()) {
            const QString what = s.info.framing == Framing::Ascii ? QStringLiteral("Modbus ASCII") : QStringLiteral("Modbus RTU");
            s.serialInterface = m_writer.addInterface(CaptureFileWriter::kLinkTypeRtacSerial, s.info.serialPort,
                                                QStringLiteral("%1 on serial port %2").arg(what, s.info.serialPort));
            QString option;
            if (s.serialInterface < 0)
                option = QStringLiteral("serial port %1 (%2) as RTU over TCP between stand-in addresses %3 -> %4, since a pcap file "
                                        "cannot name a serial port (a .pcapng file does): -o mbrtu.tcp.port:%5")
                             .arg(s.info.serialPort, what, s.info.client.toString(), s.info.server.toString())
                             .arg(s.info.serverPort);
            else if (s.info.framing == Framing::Ascii)
                option = QStringLiteral("serial port %1 (%2): tshark has no dissector for it").arg(s.info.serialPort, what);
            else
                option = QStringLiteral("serial port %1 (%2): -d rtacser.data,mbrtu").arg(s.info.serialPort, what);
            if (!m_decodeOptions.contains(option))
                m_decodeOptions.append(option);
            if (s.serialInterface < 0 && !m_rtuPorts.contains(s.info.serverPort))
                m_rtuPorts.append(s.info.serverPort);
            return s;
        }
        // A journal's ends it does not give: say which addresses stand in for them.
        const auto standIn = [&](const QString &what, const IpAddress &address, quint16 port) {
            const QString option = QStringLiteral("%1: the journal does not say the %2's address: %3:%4 stands for it")
                                       .arg(s.info.serverText(), what, address.toString())
                                       .arg(port);
            if (!m_decodeOptions.contains(option))
                m_decodeOptions.append(option);
        };
        if (!s.info.clientKnown)
            standIn(QStringLiteral("client"), s.info.client, s.info.clientPort);
        if (!s.info.serverKnown)
            standIn(QStringLiteral("server"), s.info.server, s.info.serverPort);
        if (s.info.framing == Framing::Rtu && !m_rtuPorts.contains(s.info.serverPort))
            m_rtuPorts.append(s.info.serverPort);
        const QString transport = s.info.udp ? QStringLiteral("udp") : QStringLiteral("tcp");
        QString option;
        // The Modbus dissectors tell requests from answers by their port preference, so a
        // port is given as a preference (-o), not only as "Decode As" (-d).
        if (s.info.framing == Framing::Rtu)
            option = QStringLiteral("port %1 (RTU over %2): -o mbrtu.%3.port:%1").arg(s.info.serverPort).arg(transport.toUpper(), transport);
        else if (s.info.framing == Framing::Ascii)
            option = QStringLiteral("port %1 (ASCII over %2): tshark has no dissector for it").arg(s.info.serverPort).arg(transport.toUpper());
        else if (s.info.serverPort != 502)
            option = QStringLiteral("port %1 (Modbus %2): -o %3.%4.port:%1")
                         .arg(s.info.serverPort)
                         .arg(s.info.udp ? QStringLiteral("UDP") : QStringLiteral("TCP"),
                              s.info.udp ? QStringLiteral("mbudp") : QStringLiteral("mbtcp"), transport);
        if (!option.isEmpty() && !m_decodeOptions.contains(option))
            m_decodeOptions.append(option);
    }
    return s;
}

void ExchangePcapExporter::add(const CaptureExchange &exchange)
{
    const Transaction &t = exchange.transaction;
    stream(exchange.conversation, exchange.framing);
    const bool requestWritten = exchange.kind != CaptureExchange::Kind::UnmatchedResponse && t.status != TransactionStatus::Late;
    if (requestWritten && !t.request.isEmpty()) {
        // No later exchange has an earlier request: everything held up to this one can go.
        writeUpTo(t.sentNs);
        hold(t.sentNs, exchange.conversation, true, t.request);
    }
    if (!t.response.isEmpty())
        hold(t.doneNs, exchange.conversation, false, t.response);
}

void ExchangePcapExporter::finish()
{
    writeUpTo(std::numeric_limits<qint64>::max());
}

void ExchangePcapExporter::hold(qint64 timeNs, quint32 conversation, bool toServer, const QByteArray &payload)
{
    m_held.emplace(timeNs, Held{conversation, toServer, payload});
}

void ExchangePcapExporter::writeUpTo(qint64 timeNs)
{
    while (!m_held.empty() && m_held.begin()->first <= timeNs) {
        auto node = m_held.extract(m_held.begin());
        writeOne(node.key(), node.mapped());
    }
}

void ExchangePcapExporter::writeOne(qint64 timeNs, const Held &held)
{
    Stream &s = m_streams[held.conversation];
    if (s.serialInterface >= 0) {
        // LINKTYPE_RTAC_SERIAL's header, big-endian: seconds, microseconds, event type, control
        // lines, footer.
        QByteArray packet(12, '\0');
        const quint64 t = quint64(std::max<qint64>(timeNs, 0));
        qToBigEndian(quint32(t / 1000000000ULL), packet.data());
        qToBigEndian(quint32(t % 1000000000ULL / 1000ULL), packet.data() + 4);
        packet[8] = char(held.toServer ? 0x01 : 0x02); // DATA_TX_START from the master, DATA_RX_START to it
        packet.append(held.payload);
        m_writer.write(timeNs, packet, quint32(s.serialInterface));
        return;
    }
    if (s.info.udp) {
        m_writer.write(timeNs, PacketSynthesizer::udp(s.endpoints, held.toServer, held.payload));
        return;
    }
    using P = PacketSynthesizer;
    if (!s.opened) {
        // The three-way handshake, so that Wireshark sees the connection from its start.
        m_writer.write(timeNs, P::tcp(s.endpoints, true, s.clientNext - 1, 0, P::kSyn, {}));
        m_writer.write(timeNs, P::tcp(s.endpoints, false, s.serverNext - 1, s.clientNext, P::kSyn | P::kAck, {}));
        m_writer.write(timeNs, P::tcp(s.endpoints, true, s.clientNext, s.serverNext, P::kAck, {}));
        s.opened = true;
    }
    quint32 &sequence = held.toServer ? s.clientNext : s.serverNext;
    const quint32 acknowledgement = held.toServer ? s.serverNext : s.clientNext;
    m_writer.write(timeNs, P::tcp(s.endpoints, held.toServer, sequence, acknowledgement, P::kPsh | P::kAck, held.payload));
    sequence += quint32(held.payload.size());
}

} // namespace mbscope
