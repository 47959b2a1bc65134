#include "transport/networklink.h"
#include "transport/reverselistener.h"
#include "transport/tcplink.h"

#include "linktesting.h"

#include <QtCore/QPointer>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

#include <memory>

using namespace mbscope;
using linktesting::Recorder;

// Reverse connections (issue 27, mode=listen): the link listens and is master on the connection
// the device opens, as cellular units and some gateways do (they dial out to a server and then
// expect requests). The "device" here is a QTcpSocket that connects to the link's port and
// echoes what it gets.

namespace {

constexpr int kWaitMs = 10000; // generous: a loaded machine must not fail the test

// A port on 127.0.0.1 where nothing listens: bound by the OS's choice, then released.
quint16 freePort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        qFatal("cannot bind a port");
    return server.serverPort();
}

std::unique_ptr<Link> makeLink(const QString &text)
{
    const auto parsed = LinkUrl::parse(text);
    if (!parsed.url)
        qFatal("bad URL in test: %s", qPrintable(parsed.error));
    return std::unique_ptr<Link>(Link::create(*parsed.url));
}

// A device that dials out to the link and echoes every byte it is sent.
class Device : public QObject
{
public:
    explicit Device(quint16 port)
    {
        connect(&socket, &QIODevice::readyRead, this, [this] {
            const QByteArray bytes = socket.readAll();
            got += bytes;
            if (echo)
                socket.write(bytes);
        });
        connect(&socket, &QAbstractSocket::connected, this, [this] { connected = true; });
        connect(&socket, &QAbstractSocket::disconnected, this, [this] { ++disconnected; });
        socket.connectToHost(QHostAddress::LocalHost, port);
    }
    // "127.0.0.1:40312": where the link sees it come from.
    [[nodiscard]] QString endpoint() const { return QStringLiteral("127.0.0.1:%1").arg(socket.localPort()); }

    QTcpSocket socket;
    bool echo = true;
    bool connected = false;
    int disconnected = 0;
    QByteArray got;
};

// One request out and its echo back: the link is open on the device that echoes.
bool roundTrip(Link &link, Recorder &rec, const QByteArray &bytes)
{
    const QByteArray before = rec.received;
    if (!link.write(bytes))
        return false;
    return QTest::qWaitFor([&] { return rec.received == before + bytes; }, kWaitMs);
}

} // namespace

class TestReverseLink : public QObject
{
    Q_OBJECT
private slots:
    // tcp, rtu-tcp and ascii-tcp all listen with mode=listen; the link is a TcpLink.
    void opensWhenTheDeviceConnects_data()
    {
        QTest::addColumn<QString>("scheme");
        QTest::newRow("tcp") << QStringLiteral("tcp");
        QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp");
        QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp");
    }
    void opensWhenTheDeviceConnects()
    {
        QFETCH(QString, scheme);
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("%1://127.0.0.1:%2?mode=listen").arg(scheme).arg(port));
        QVERIFY(qobject_cast<TcpLink *>(link.get()));
        Recorder rec(link.get());
        link->open();
        QCOMPARE(link->state(), Link::State::Opening);
        Device device(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QVERIFY2(rec.errors.isEmpty(), qPrintable(rec.lastMessage()));
        QCOMPARE(link->state(), Link::State::Open);
        QTRY_VERIFY_WITH_TIMEOUT(device.connected, kWaitMs);
        // The journal's endpoints: our listening address, and the device's.
        const auto *network = qobject_cast<NetworkLink *>(link.get());
        QCOMPARE(network->localEndpoint(), QStringLiteral("127.0.0.1:%1").arg(port));
        QCOMPARE(network->peerEndpoint(), device.endpoint());
        QVERIFY(roundTrip(*link, rec, "01 03 00 79 00 16"));
        QCOMPARE(device.got, QByteArray("01 03 00 79 00 16"));
        QCOMPARE(rec.writtenNs.size(), 1);
    }

    // Nobody dials in: the connect timeout ends the wait, and the message says where we waited.
    void noDeviceConnects_data()
    {
        QTest::addColumn<QString>("timeout");
        QTest::addColumn<QString>("said");
        QTest::newRow("200ms") << QStringLiteral("200ms") << QStringLiteral("200 ms");
        QTest::newRow("1s") << QStringLiteral("1s") << QStringLiteral("1 s");
    }
    void noDeviceConnects()
    {
        QFETCH(QString, timeout);
        QFETCH(QString, said);
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen&connect_timeout=%2").arg(port).arg(timeout));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Timeout);
        QCOMPARE(rec.lastMessage(), link->url().toString()
                     + QStringLiteral(": no device connected to 127.0.0.1:%1 within %2 (connect timeout): the device must "
                                      "connect to this address and port")
                           .arg(port)
                           .arg(said));
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.opened, 0);
        // Still listening: a device that dials now is taken by the next open().
        Device device(port);
        QTRY_VERIFY_WITH_TIMEOUT(device.connected, kWaitMs);
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QVERIFY(roundTrip(*link, rec, "late"));
    }

    // The device drops and dials again: the link is lost, and the next open() uses the new
    // connection (here it is waiting already when open() comes).
    void deviceReconnects()
    {
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen").arg(port));
        Recorder rec(link.get());
        link->open();
        auto first = std::make_unique<Device>(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        const QString firstEnd = first->endpoint();
        QVERIFY(roundTrip(*link, rec, "one"));
        first->socket.disconnectFromHost();
        QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
        QCOMPARE(rec.errors.size(), 1);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Closed);
        QCOMPARE(rec.lastMessage(), link->url().toString() + QStringLiteral(": the device at %1 closed the connection").arg(firstEnd));
        QCOMPARE(rec.closed, 1);

        Device second(port);
        QTRY_VERIFY_WITH_TIMEOUT(second.connected, kWaitMs);
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QCOMPARE(qobject_cast<NetworkLink *>(link.get())->peerEndpoint(), second.endpoint());
        QVERIFY(roundTrip(*link, rec, "two"));
        QCOMPARE(second.got, QByteArray("two"));
        QCOMPARE(first->got, QByteArray("one"));
    }

    // A connection that waited and was closed by its device before open() is passed over.
    void closedWhileWaiting()
    {
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen&busy=queue&connect_timeout=1s").arg(port));
        Recorder rec(link.get());
        link->open();
        Device first(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        auto *listener = link->findChild<ReverseListener *>();
        QVERIFY(listener);
        auto gone = std::make_unique<Device>(port);
        QTRY_COMPARE_WITH_TIMEOUT(listener->waitingCount(), 1, kWaitMs);
        gone->socket.disconnectFromHost();
        QTRY_VERIFY_WITH_TIMEOUT(gone->socket.state() == QAbstractSocket::UnconnectedState, kWaitMs);
        gone.reset();
        Device third(port);
        QTRY_COMPARE_WITH_TIMEOUT(listener->waitingCount(), 2, kWaitMs);
        first.socket.disconnectFromHost();
        QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QCOMPARE(qobject_cast<NetworkLink *>(link.get())->peerEndpoint(), third.endpoint());
        QVERIFY(roundTrip(*link, rec, "third"));
        QCOMPARE(listener->waitingCount(), 0);
    }

    // A second device connects while the first is in use: busy= decides.
    void secondConnection_data()
    {
        QTest::addColumn<QString>("busy");
        QTest::newRow("replace (the default)") << QString();
        QTest::newRow("replace") << QStringLiteral("&busy=replace");
        QTest::newRow("queue") << QStringLiteral("&busy=queue");
        QTest::newRow("refuse") << QStringLiteral("&busy=refuse");
    }
    void secondConnection()
    {
        QFETCH(QString, busy);
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen&connect_timeout=1s").arg(port) + busy);
        const BusyPolicy policy = link->url().busy;
        Recorder rec(link.get());
        link->open();
        Device first(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QVERIFY(roundTrip(*link, rec, "a"));
        const QString firstEnd = first.endpoint(); // while it is connected
        auto *listener = link->findChild<ReverseListener *>();
        QVERIFY(listener);
        Device second(port);
        QTRY_VERIFY_WITH_TIMEOUT(second.connected, kWaitMs);

        switch (policy) {
        case BusyPolicy::Replace:
            // The one in use goes, and the next open() takes the new one.
            QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
            QCOMPARE(rec.errors.size(), 1);
            QCOMPARE(rec.errors.first().kind, LinkError::Kind::Closed);
            QCOMPARE(rec.lastMessage(), link->url().toString()
                         + QStringLiteral(": the device at %1 is replaced by a new connection from %2 (busy=replace); the "
                                          "next request uses it")
                               .arg(firstEnd, second.endpoint()));
            QTRY_COMPARE_WITH_TIMEOUT(first.disconnected, 1, kWaitMs);
            link->open();
            QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
            QVERIFY(roundTrip(*link, rec, "b"));
            QCOMPARE(second.got, QByteArray("b"));
            break;
        case BusyPolicy::Queue:
            // It waits until the first ends.
            QTRY_COMPARE_WITH_TIMEOUT(listener->waitingCount(), 1, kWaitMs);
            QVERIFY(roundTrip(*link, rec, "b"));
            QCOMPARE(first.got, QByteArray("ab"));
            first.socket.disconnectFromHost();
            QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
            link->open();
            QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
            QVERIFY(roundTrip(*link, rec, "c"));
            QCOMPARE(second.got, QByteArray("c"));
            break;
        case BusyPolicy::Refuse:
            // Closed at once; the first goes on, and once it ends nobody is left.
            QTRY_COMPARE_WITH_TIMEOUT(second.disconnected, 1, kWaitMs);
            QCOMPARE(listener->turnedAway(), quint64(1));
            QVERIFY(roundTrip(*link, rec, "b"));
            QCOMPARE(first.got, QByteArray("ab"));
            first.socket.disconnectFromHost();
            QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
            link->open();
            QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 2, kWaitMs);
            QCOMPARE(rec.errors.last().kind, LinkError::Kind::Timeout);
            QCOMPARE(second.got, QByteArray());
            break;
        }
    }

    // close() on request keeps the device's connection for the next open() (a scan or a watch
    // closes between its phases; the device would have to dial again): bytes that came while it
    // was parked are dropped, they answer nothing the next open asks.
    void closeParksTheConnection()
    {
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen").arg(port));
        Recorder rec(link.get());
        link->open();
        Device device(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        const QString peer = qobject_cast<NetworkLink *>(link.get())->peerEndpoint();
        QVERIFY(roundTrip(*link, rec, "x"));
        link->close();
        QCOMPARE(rec.closed, 1);
        QCOMPARE(link->state(), Link::State::Closed);
        auto *listener = link->findChild<ReverseListener *>();
        QCOMPARE(listener->waitingCount(), 1);
        device.socket.write("stale");
        QVERIFY(device.socket.waitForBytesWritten(kWaitMs) || device.socket.bytesToWrite() == 0);
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QCOMPARE(qobject_cast<NetworkLink *>(link.get())->peerEndpoint(), peer);
        QVERIFY(roundTrip(*link, rec, "y"));
        QCOMPARE(rec.received, QByteArray("xy"));
        QCOMPARE(device.disconnected, 0);
        QCOMPARE(device.got, QByteArray("xy"));
        QVERIFY(rec.errors.isEmpty());
    }

    // The link's end frees the port and ends the connections it held.
    void destroyingTheLinkReleasesThePort()
    {
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?mode=listen&busy=queue").arg(port));
        Recorder rec(link.get());
        link->open();
        Device inUse(port);
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        Device waiting(port);
        QTRY_COMPARE_WITH_TIMEOUT(link->findChild<ReverseListener *>()->waitingCount(), 1, kWaitMs);
        link.reset();
        QTRY_COMPARE_WITH_TIMEOUT(inUse.disconnected, 1, kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(waiting.disconnected, 1, kWaitMs);
        QTcpServer again;
        QVERIFY2(again.listen(QHostAddress::LocalHost, port), qPrintable(again.errorString()));
    }

    // Another program has the port: said at open(), with the address.
    void addressInUse()
    {
        QTcpServer other;
        QVERIFY(other.listen(QHostAddress::LocalHost, 0));
        auto link = makeLink(QStringLiteral("rtu-tcp://127.0.0.1:%1?mode=listen").arg(other.serverPort()));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Io);
        QCOMPARE(rec.lastMessage(), link->url().toString()
                     + QStringLiteral(": cannot wait for a device to connect: address in use: another program listens on "
                                      "127.0.0.1:%1 already")
                           .arg(other.serverPort()));
        QCOMPARE(link->state(), Link::State::Closed);
    }

    // Without mode=listen nothing listens (the default is to connect).
    void connectIsTheDefault()
    {
        const quint16 port = freePort();
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1?connect_timeout=2s").arg(port));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Refused);
        QVERIFY(!link->findChild<ReverseListener *>());
    }
};

QTEST_GUILESS_MAIN(TestReverseLink)
#include "tst_reverselink.moc"
