// Frames that answer no request reach the window's traffic list with their verdicts: a device
// server (a QTcpServer in the test, on a port from the OS) answers a read, sends a copy of the
// answer, then a frame nobody asked for and bytes that are no frame at all. The window's list
// shows the request, the answer, the duplicate and the unsolicited frame as "unsolicited", and the
// garbage as "garbage", all on the link's URL, and the Link, Unit and Length columns read them.
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "shell/mainwindow.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"

#include <QtCore/QTimer>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 5000;

// An RTU frame: unit and PDU with its CRC-16/MODBUS, low byte first (Serial Line V1.02, 2.5.1.2).
QByteArray withCrc(QByteArray pdu)
{
    quint16 crc = 0xFFFF;
    for (const char c : std::as_const(pdu)) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? (crc >> 1) ^ 0xA001 : crc >> 1;
    }
    pdu.append(char(crc & 0xFF));
    pdu.append(char(crc >> 8));
    return pdu;
}

// A serial device server whose device misbehaves in a scripted way: what it writes after each
// request it reads, and what it writes a little later, unasked.
class ChattyDevice : public QObject
{
public:
    QByteArray answer;
    QByteArray unasked;

    bool listen()
    {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = m_server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                socket->readAll();
                socket->write(answer);
                QTimer::singleShot(100, socket, [this, socket] { socket->write(unasked); });
            });
        });
        return m_server.listen(QHostAddress::LocalHost, 0);
    }
    [[nodiscard]] quint16 port() const { return m_server.serverPort(); }

private:
    QTcpServer m_server;
};

} // namespace

class TestUnmatchedTraffic : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void framesOfNoTransactionAreListed_data();
    void framesOfNoTransactionAreListed();
};

void TestUnmatchedTraffic::framesOfNoTransactionAreListed_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    QTest::addColumn<QByteArray>("unasked");
    QTest::addColumn<QStringList>("verdicts");
    QTest::addColumn<QStringList>("units");
    QTest::addColumn<QString>("shot");

    const QByteArray read = withCrc(QByteArray::fromHex("010300790001"));
    const QByteArray answer = withCrc(QByteArray::fromHex("010302002A"));
    // Unit 5's answer to a read nobody sent, then bytes with a wrong CRC that frame nothing.
    const QByteArray stray = withCrc(QByteArray::fromHex("0503020007"));
    const QByteArray garbage = QByteArray::fromHex("00FF1337C0DE");
    QTest::newRow("answer, its duplicate, a stray frame, garbage")
        << read << answer + answer << stray + garbage
        << QStringList{QStringLiteral("sent"), QStringLiteral("ok"), QStringLiteral("unsolicited"),
                       QStringLiteral("unsolicited"), QStringLiteral("garbage")}
        << QStringList{QStringLiteral("1"), QStringLiteral("1"), QStringLiteral("1"), QStringLiteral("5"), QString()}
        << QStringLiteral("traffic-unmatched.png");
    QTest::newRow("only garbage after the answer")
        << read << answer << garbage
        << QStringList{QStringLiteral("sent"), QStringLiteral("ok"), QStringLiteral("garbage")}
        << QStringList{QStringLiteral("1"), QStringLiteral("1"), QString()} << QStringLiteral("traffic-garbage.png");
}

void TestUnmatchedTraffic::framesOfNoTransactionAreListed()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    QFETCH(QByteArray, unasked);
    QFETCH(QStringList, verdicts);
    QFETCH(QStringList, units);
    QFETCH(QString, shot);

    ChattyDevice device;
    device.answer = answer;
    device.unasked = unasked;
    QVERIFY(device.listen());
    const LinkUrl::Result target = LinkUrl::parse(QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(device.port()));
    QVERIFY2(target.url, qPrintable(target.error));

    MainWindow window;
    TrafficModel *model = window.trafficMonitor()->model();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    window.controller()->connectTo(*target.url);
    QVERIFY(window.controller()->send(request) > 0);

    QTRY_COMPARE_WITH_TIMEOUT(model->rowCount(), int(verdicts.size()), kWaitMs);
    QTest::qWait(200); // nothing more comes: no frame is listed twice
    QCOMPARE(model->rowCount(), int(verdicts.size()));
    const auto text = [model](int row, int column) { return model->data(model->index(row, column)).toString(); };
    for (int row = 0; row < verdicts.size(); ++row) {
        QCOMPARE(text(row, TrafficModel::VerdictColumn), verdicts.at(row));
        QCOMPARE(text(row, TrafficModel::LinkColumn), target.url->toString());
        QCOMPARE(text(row, TrafficModel::UnitColumn), units.at(row));
        QCOMPARE(text(row, TrafficModel::DirectionColumn).isEmpty(), false);
    }
    const int last = int(verdicts.size()) - 1;
    QCOMPARE(model->data(model->index(last, 0), TrafficModel::BytesRole).toByteArray(),
             unasked.right(6)); // the garbage, as read
    QCOMPARE(model->data(model->index(last, 0), TrafficModel::DirectionRole).toInt(), int(TrafficDirection::In));
    window.trafficMonitor()->resize(1000, 300);
    QVERIFY(guitest::saveShot(window.trafficMonitor(), shot));
}

QTEST_MAIN(TestUnmatchedTraffic)
#include "tst_unmatchedtraffic.moc"
