// A session's requests become bytes on the wire only when the link is known: exact hex is sent
// as typed on every link; a form, or hex marked as a PDU to complete, gets the link's framing
// (MBAP header, RTU CRC, ASCII LRC) and its keys for matching the answer.

#include "session/sessionrequest.h"

#include "protocol/hextext.h"
#include "transport/linkurl.h"

#include <QtTest/QtTest>

using namespace mbscope;

Q_DECLARE_METATYPE(mbscope::SessionRequest)

namespace {

SessionRequest form(int function, int address, int quantity, int unit = 1)
{
    SessionRequest r;
    r.kind = SessionRequest::Kind::Form;
    r.function = function;
    r.address = address;
    r.quantity = quantity;
    r.unit = unit;
    return r;
}

SessionRequest hex(const QString &text, bool complete = false, int unit = 1)
{
    SessionRequest r;
    r.hex = text;
    r.complete = complete;
    r.unit = unit;
    return r;
}

} // namespace

class TestSessionRequest : public QObject
{
    Q_OBJECT

private slots:
    void wireBytes_data();
    void wireBytes();
};

void TestSessionRequest::wireBytes_data()
{
    QTest::addColumn<SessionRequest>("request");
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("bytes"); // empty: refused
    QTest::addColumn<QString>("error");

    // The RosRao request of the lab (01 03 00 79 00 16 15 DD), built from a form.
    QTest::newRow("form on rtu-tcp") << form(3, 0x79, 22) << "rtu-tcp://127.0.0.1:4001"
                                     << HexText::parse(u"01 03 00 79 00 16 15 DD").bytes << QString();
    QTest::newRow("form on tcp: MBAP, transaction id 7") << form(3, 0x79, 22) << "tcp://127.0.0.1:502"
                                                         << HexText::parse(u"00 07 00 00 00 06 01 03 00 79 00 16").bytes << QString();
    // LRC: 0x100 - (01 + 03 + 00 + 79 + 00 + 16 = 0x93) = 0x6D (Serial Line V1.02, 2.5.2.2).
    QTest::newRow("form on ascii-tcp") << form(3, 0x79, 22) << "ascii-tcp://127.0.0.1:4002"
                                       << QByteArray(":0103007900166D\r\n") << QString();
    QTest::newRow("exact hex never rewritten") << hex(QStringLiteral("01 03 00 79 00 16 15 DE")) << "tcp://127.0.0.1:502"
                                               << HexText::parse(u"01 03 00 79 00 16 15 DE").bytes << QString();
    QTest::newRow("hex completed for rtu, unit 3") << hex(QStringLiteral("03 00 79 00 0D"), true, 3) << "rtu-tcp://127.0.0.1:4001"
                                                   << HexText::parse(u"03 03 00 79 00 0D 54 34").bytes << QString();
    QTest::newRow("write registers on udp") << [] {
        SessionRequest r = form(16, 0x7F, 0);
        r.values = {2000};
        return r;
    }() << "udp://127.0.0.1:502" << HexText::parse(u"00 07 00 00 00 09 01 10 00 7F 00 01 02 07 D0").bytes << QString();
    QTest::newRow("completion on a delimited link") << form(3, 0, 1) << "tcp://127.0.0.1:502?framing=delimited"
                                                    << QByteArray()
                                                    << "tcp://127.0.0.1:502?framing=delimited&end=0A uses delimited framing: a Modbus header or "
                                                       "checksum cannot be added; give the exact bytes as hex";
    QTest::newRow("out of spec") << form(3, 0, 126) << "tcp://127.0.0.1:502" << QByteArray()
                                 << "quantity 126 is out of range: Read Holding Registers reads 1-125 registers";
}

void TestSessionRequest::wireBytes()
{
    QFETCH(SessionRequest, request);
    QFETCH(QString, url);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, error);
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    QVERIFY2(parsed.url, qPrintable(parsed.error));
    const SessionRequest::Bytes made = request.wireBytes(*parsed.url, 7);
    QCOMPARE(made.error, error);
    QCOMPARE(made.bytes.toHex(' '), bytes.toHex(' '));
}

QTEST_GUILESS_MAIN(TestSessionRequest)
#include "tst_sessionrequest.moc"
