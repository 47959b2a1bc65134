// PacketDecoder: the same TCP segment and UDP datagram (made by PacketSynthesizer, whose
// checksums are verified here too) under every link type a capture of Modbus traffic comes in,
// plus the packets it must refuse or count apart.
#include "capture/packetdecoder.h"
#include "capture/packetsynthesizer.h"

#include <QtTest/QTest>

using namespace mbscope;

namespace {

PacketSynthesizer::Endpoints endpoints(bool v6)
{
    PacketSynthesizer::Endpoints e;
    e.clientPort = 50123;
    e.serverPort = 502;
    if (v6) {
        e.client.v6 = e.server.v6 = true;
        e.client.bytes[15] = 1;
        e.server.bytes[15] = 1; // ::1 to ::1, as on a loopback
    } else {
        e.client.bytes = {127, 0, 0, 1};
        e.server.bytes = {127, 0, 0, 2};
    }
    return e;
}

const QByteArray kPayload = QByteArray::fromHex("000100000006010300000002");

// The IP packet inside an Ethernet frame made by the synthesizer.
QByteArray ipOf(const QByteArray &ethernet)
{
    return ethernet.mid(14);
}

QByteArray be16(quint16 v)
{
    return QByteArray(1, char(v >> 8)) + char(v & 0xff);
}

} // namespace

class TestPacketDecoder : public QObject
{
    Q_OBJECT

private slots:
    void linkTypes_data();
    void linkTypes();
    void refused_data();
    void refused();
    void checksumsVerify_data();
    void checksumsVerify();
};

void TestPacketDecoder::linkTypes_data()
{
    QTest::addColumn<quint32>("linkType");
    QTest::addColumn<QByteArray>("packet");
    QTest::addColumn<bool>("udp");
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<QString>("source");

    const QByteArray tcp4 = PacketSynthesizer::tcp(endpoints(false), true, 1000, 2000, 0x18, kPayload);
    const QByteArray tcp6 = PacketSynthesizer::tcp(endpoints(true), true, 1000, 2000, 0x18, kPayload);
    const QByteArray udp4 = PacketSynthesizer::udp(endpoints(false), true, kPayload);
    const QString v4 = QStringLiteral("127.0.0.1");
    QTest::newRow("ethernet ipv4 tcp") << 1u << tcp4 << false << kPayload << v4;
    QTest::newRow("ethernet ipv6 tcp") << 1u << tcp6 << false << kPayload << QStringLiteral("::1");
    QTest::newRow("ethernet ipv4 udp") << 1u << udp4 << true << kPayload << v4;
    QTest::newRow("ethernet 802.1Q tag") << 1u << tcp4.left(12) + QByteArray::fromHex("81000064") + tcp4.mid(12) << false << kPayload << v4;
    {
        const QByteArray small = PacketSynthesizer::tcp(endpoints(false), true, 1, 1, 0x18, "ab");
        QTest::newRow("ethernet padding is not payload") << 1u << small + QByteArray(60 - small.size(), '\0') << false << QByteArray("ab") << v4;
    }
    QTest::newRow("linux cooked v1") << 113u << QByteArray(14, '\0') + be16(0x0800) + ipOf(tcp4) << false << kPayload << v4;
    QTest::newRow("linux cooked v2") << 276u << be16(0x0800) + QByteArray(18, '\0') + ipOf(tcp4) << false << kPayload << v4;
    QTest::newRow("bsd loopback, little-endian family") << 0u << QByteArray::fromHex("02000000") + ipOf(tcp4) << false << kPayload << v4;
    QTest::newRow("bsd loopback, ipv6 family 30") << 0u << QByteArray::fromHex("1e000000") + ipOf(tcp6) << false << kPayload << QStringLiteral("::1");
    QTest::newRow("openbsd loopback") << 108u << QByteArray::fromHex("00000002") + ipOf(tcp4) << false << kPayload << v4;
    QTest::newRow("raw ip") << 101u << ipOf(tcp4) << false << kPayload << v4;
    QTest::newRow("raw ipv6 (229)") << 229u << ipOf(tcp6) << false << kPayload << QStringLiteral("::1");
}

void TestPacketDecoder::linkTypes()
{
    QFETCH(quint32, linkType);
    QFETCH(QByteArray, packet);
    QFETCH(bool, udp);
    QFETCH(QByteArray, payload);
    QFETCH(QString, source);
    CapturePacket p;
    p.linkType = linkType;
    p.data = packet;
    p.originalLength = quint32(packet.size());
    const DecodedPacket d = PacketDecoder::decode(p);
    QCOMPARE(int(d.outcome), int(udp ? DecodedPacket::Outcome::Udp : DecodedPacket::Outcome::Tcp));
    QCOMPARE(d.sourcePort, quint16(50123));
    QCOMPARE(d.destinationPort, quint16(502));
    QCOMPARE(d.source.toString(), source);
    QCOMPARE(d.payload.toByteArray(), payload);
    QVERIFY(!d.truncated);
    if (!udp && payload == kPayload)
        QCOMPARE(d.sequence, 1000u);
}

void TestPacketDecoder::refused_data()
{
    QTest::addColumn<quint32>("linkType");
    QTest::addColumn<QByteArray>("packet");
    QTest::addColumn<int>("outcome");
    QTest::addColumn<QString>("problem");

    const QByteArray tcp4 = PacketSynthesizer::tcp(endpoints(false), true, 1000, 2000, 0x18, kPayload);
    QByteArray fragment = tcp4;
    fragment[14 + 6] = char(0x20); // more fragments
    QByteArray badHeader = tcp4;
    badHeader[14] = char(0x44); // IHL 4: 16 bytes
    QTest::newRow("arp") << 1u << QByteArray(12, '\0') + be16(0x0806) + QByteArray(28, '\0') << int(DecodedPacket::Outcome::NotIp) << QString();
    QTest::newRow("ipv4 fragment") << 1u << fragment << int(DecodedPacket::Outcome::Fragment) << QString();
    QTest::newRow("ipv4 header length 16") << 1u << badHeader << int(DecodedPacket::Outcome::Malformed)
                                          << QStringLiteral("IPv4 header length below 20");
    QTest::newRow("ethernet cut") << 1u << tcp4.left(10) << int(DecodedPacket::Outcome::Malformed) << QStringLiteral("Ethernet header cut short");
    QTest::newRow("tcp header cut by the snap length") << 1u << tcp4.left(14 + 20 + 10) << int(DecodedPacket::Outcome::Malformed)
                                                      << QStringLiteral("TCP header cut by the snap length");
    QTest::newRow("unknown link type") << 147u << tcp4 << int(DecodedPacket::Outcome::UnknownLinkType) << QString();
}

void TestPacketDecoder::refused()
{
    QFETCH(quint32, linkType);
    QFETCH(QByteArray, packet);
    QFETCH(int, outcome);
    QFETCH(QString, problem);
    CapturePacket p;
    p.linkType = linkType;
    p.data = packet;
    p.originalLength = 200;
    const DecodedPacket d = PacketDecoder::decode(p);
    QCOMPARE(int(d.outcome), outcome);
    if (!problem.isEmpty())
        QCOMPARE(QString::fromLatin1(d.problem), problem);
}

// Summing a header or segment with its checksum (and the pseudo-header) gives 0 (RFC 1071).
void TestPacketDecoder::checksumsVerify_data()
{
    QTest::addColumn<bool>("v6");
    QTest::addColumn<bool>("udp");
    QTest::addColumn<int>("payloadSize");
    for (const bool v6 : {false, true}) {
        for (const bool udp : {false, true}) {
            for (const int size : {0, 1, 12, 259})
                QTest::addRow("%s %s %d bytes", v6 ? "ipv6" : "ipv4", udp ? "udp" : "tcp", size) << v6 << udp << size;
        }
    }
}

void TestPacketDecoder::checksumsVerify()
{
    QFETCH(bool, v6);
    QFETCH(bool, udp);
    QFETCH(int, payloadSize);
    QByteArray payload(payloadSize, '\0');
    for (int i = 0; i < payloadSize; ++i)
        payload[i] = char(i * 37 + 11);
    const PacketSynthesizer::Endpoints e = endpoints(v6);
    const QByteArray frame = udp ? PacketSynthesizer::udp(e, false, payload) : PacketSynthesizer::tcp(e, false, 7, 9, 0x18, payload);
    const QByteArray ip = frame.mid(14);
    const int ipHeader = v6 ? 40 : 20;
    if (!v6)
        QCOMPARE(PacketSynthesizer::internetChecksum(ip.left(20)), quint16(0));
    const QByteArray transport = ip.mid(ipHeader);
    QByteArray pseudo = v6 ? ip.mid(8, 32) : ip.mid(12, 8);
    pseudo += v6 ? QByteArray::fromHex("0000") + be16(quint16(transport.size())) + QByteArray::fromHex("000000") + char(udp ? 17 : 6)
                 : QByteArray(1, '\0') + char(udp ? 17 : 6) + be16(quint16(transport.size()));
    QCOMPARE(PacketSynthesizer::internetChecksum(pseudo + transport), quint16(0));
}

QTEST_GUILESS_MAIN(TestPacketDecoder)
#include "tst_packetdecoder.moc"
