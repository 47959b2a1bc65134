#include "transport/monotonicclock.h"
#include "transport/tcplink.h"

#include "linktesting.h"

#include <QtCore/QPointer>
#include <QtCore/QScopeGuard>
#include <QtCore/QThread>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

#include <memory>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

using namespace mbscope;
using linktesting::Recorder;

namespace {

constexpr int kWaitMs = 10000; // generous: a loaded machine must not fail the test

// A loopback peer on a port the OS chose: echoes, or does what a test tells it.
class Peer : public QObject
{
public:
    Peer()
    {
        QVERIFY(m_server.listen(QHostAddress::LocalHost, 0));
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = m_server.nextPendingConnection()) {
                ++accepted;
                last = socket;
                connect(socket, &QIODevice::readyRead, socket, [this, socket] {
                    const QByteArray bytes = socket->readAll();
                    got += bytes;
                    if (echo)
                        socket->write(bytes);
                });
                connect(socket, &QAbstractSocket::disconnected, this, [this] { ++disconnected; });
            }
        });
    }
    [[nodiscard]] quint16 port() const { return m_server.serverPort(); }
    [[nodiscard]] QString url(const QString &options = {}) const
    {
        return QStringLiteral("tcp://127.0.0.1:%1").arg(port()) + options;
    }

    bool echo = true;
    int accepted = 0;
    int disconnected = 0;
    QByteArray got;
    QPointer<QTcpSocket> last;

private:
    QTcpServer m_server;
};

std::unique_ptr<Link> makeLink(const QString &text)
{
    const auto parsed = LinkUrl::parse(text);
    if (!parsed.url)
        qFatal("bad URL in test: %s", qPrintable(parsed.error));
    return std::unique_ptr<Link>(Link::create(*parsed.url));
}

// A port nothing listens on: bound by the OS, then released.
quint16 closedPort()
{
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    const quint16 port = server.serverPort();
    server.close();
    return port;
}

} // namespace

class TestTcpLink : public QObject
{
    Q_OBJECT
private slots:
    void createsTcpLinks_data()
    {
        QTest::addColumn<QString>("url");
        QTest::newRow("tcp") << QStringLiteral("tcp://127.0.0.1:502");
        QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:4001");
        QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:4002");
    }
    void createsTcpLinks()
    {
        QFETCH(QString, url);
        auto link = makeLink(url);
        QVERIFY(qobject_cast<TcpLink *>(link.get()));
        QVERIFY(!link->isDatagram());
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(link->t35Ns(), qint64(0));
        QCOMPARE(link->turnaroundNs(), qint64(0));
    }

    void echo()
    {
        Peer peer;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        QCOMPARE(link->state(), Link::State::Opening);
        QCOMPARE(rec.opened, 0); // signalled after open() returns
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QCOMPARE(link->state(), Link::State::Open);
        // TCP_NODELAY is on, so that a request is not held back by Nagle's algorithm.
        const auto *tcp = qobject_cast<TcpLink *>(link.get());
        QVERIFY(tcp);
        QVERIFY(tcp->socketDescriptor() >= 0);
        int noDelay = 0;
        socklen_t size = sizeof noDelay;
        QCOMPARE(::getsockopt(int(tcp->socketDescriptor()), IPPROTO_TCP, TCP_NODELAY, &noDelay, &size), 0);
        QCOMPARE(noDelay, 1);

        const QByteArray request = QByteArray::fromHex("000100000006010300790016");
        const qint64 before = monotonicNowNs();
        QVERIFY(link->write(request));
        QTRY_COMPARE_WITH_TIMEOUT(rec.writtenNs.size(), 1, kWaitMs);
        QVERIFY(rec.writtenNs.first() >= before);
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, request, kWaitMs);
        QCOMPARE(peer.got, request);
        for (int i = 0; i < rec.chunks.size(); ++i) {
            QCOMPARE(rec.firstNs.at(i), rec.lastNs.at(i)); // one read, one time
            QVERIFY(rec.firstNs.at(i) >= rec.writtenNs.first()); // the echo follows the write
        }
        QVERIFY(rec.errors.isEmpty());
    }

    // Several writes in flight: one bytesWritten each, in order.
    void pipelinedWrites()
    {
        Peer peer;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QByteArray all;
        for (int i = 0; i < 5; ++i) {
            const QByteArray frame = QByteArray::fromHex("0000000000060103000000") + char(i);
            all += frame;
            QVERIFY(link->write(frame));
        }
        QTRY_COMPARE_WITH_TIMEOUT(rec.writtenNs.size(), 5, kWaitMs);
        QVERIFY(std::is_sorted(rec.writtenNs.begin(), rec.writtenNs.end()));
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, all, kWaitMs);
    }

    // A peer that does not read fills the kernel's buffers: writes are still taken whole, the
    // rest leaves when the peer reads, each write is reported once, in order, once all of it has
    // left, and the bytes arrive intact and in order.
    void writesLargerThanTheKernelTakes_data()
    {
        QTest::addColumn<int>("writes");
        QTest::addColumn<int>("bytesEach");
        QTest::newRow("4 x 1 MiB") << 4 << 1024 * 1024;
        QTest::newRow("64 x 64 KiB") << 64 << 64 * 1024;
    }
    void writesLargerThanTheKernelTakes()
    {
        QFETCH(int, writes);
        QFETCH(int, bytesEach);
        const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
        QVERIFY(listener >= 0);
        auto closeListener = qScopeGuard([&] { ::close(listener); });
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        // A small receive buffer (inherited by the accepted socket; no autotuning then): the
        // link's writes outgrow what the kernel holds whatever the system's defaults.
        const int small = 64 * 1024;
        QCOMPARE(::setsockopt(listener, SOL_SOCKET, SO_RCVBUF, &small, sizeof small), 0);
        QCOMPARE(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address), 0);
        QCOMPARE(::listen(listener, 1), 0);
        socklen_t length = sizeof address;
        QCOMPARE(::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length), 0);
        auto link = makeLink(QStringLiteral("tcp://127.0.0.1:%1").arg(ntohs(address.sin_port)));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        const int peer = ::accept4(listener, nullptr, nullptr, SOCK_NONBLOCK);
        QVERIFY(peer >= 0);
        auto closePeer = qScopeGuard([&] { ::close(peer); });

        QByteArray sent;
        for (int w = 0; w < writes; ++w) {
            QByteArray chunk(bytesEach, Qt::Uninitialized);
            for (int i = 0; i < bytesEach; ++i)
                chunk[i] = char((w * 131 + i) & 0xFF);
            QVERIFY(link->write(chunk));
            sent += chunk;
        }
        QVERIFY2(rec.writtenNs.size() < writes, "the kernel took everything: the test proves nothing");
        QByteArray got;
        char buffer[65536];
        // Read as it comes, letting the link send the rest between reads.
        QDeadlineTimer deadline(kWaitMs);
        while (got.size() < sent.size() && !deadline.hasExpired()) {
            const ssize_t n = ::recv(peer, buffer, sizeof buffer, 0);
            if (n > 0)
                got.append(buffer, n);
            else
                QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        }
        QVERIFY(got == sent);
        QTRY_COMPARE_WITH_TIMEOUT(rec.writtenNs.size(), writes, kWaitMs);
        QVERIFY(std::is_sorted(rec.writtenNs.begin(), rec.writtenNs.end()));
        QVERIFY(rec.errors.isEmpty());
    }

    void closeAndReopen()
    {
        Peer peer;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        link->open(); // already open: nothing happens
        link->close();
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.closed, 1);
        QCOMPARE(rec.closedReasons.first(), QStringLiteral("closed on request"));
        QTRY_COMPARE_WITH_TIMEOUT(peer.disconnected, 1, kWaitMs);
        link->close(); // already closed: nothing happens
        QCOMPARE(rec.closed, 1);

        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QCOMPARE(peer.accepted, 2);
        QVERIFY(link->write("again"));
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, QByteArray("again"), kWaitMs);
        QVERIFY(rec.errors.isEmpty());
    }

    // Closed while opening: no opened(), one closed().
    void closeWhileOpening()
    {
        Peer peer;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        link->close();
        QCOMPARE(rec.closed, 1);
        QTest::qWait(50);
        QCOMPARE(rec.opened, 0);
        QCOMPARE(link->state(), Link::State::Closed);
    }

    // The peer closes mid-frame: the bytes it sent come first, then the error and closed(), and
    // the next open() connects again.
    void peerClosesMidFrame()
    {
        Peer peer;
        peer.echo = false;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(peer.last, kWaitMs);
        peer.last->write(QByteArray::fromHex("0001000000"));
        peer.last->flush();
        peer.last->disconnectFromHost();
        QTRY_COMPARE_WITH_TIMEOUT(rec.closed, 1, kWaitMs);
        QCOMPARE(rec.received, QByteArray::fromHex("0001000000"));
        QCOMPARE(rec.events.last(), QStringLiteral("closed"));
        QCOMPARE(rec.events.at(rec.events.size() - 2), QStringLiteral("error closed"));
        QCOMPARE(rec.events.indexOf(QStringLiteral("received")), 1);
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.lastMessage(), peer.url() + QStringLiteral(": 127.0.0.1:%1 closed the connection").arg(peer.port()));
        QCOMPARE(rec.closedReasons.first(), rec.lastMessage());

        QVERIFY(!link->write("x"));
        QCOMPARE(rec.errors.last().kind, LinkError::Kind::Closed);
        QCOMPARE(rec.lastMessage(), peer.url() + QStringLiteral(": cannot write 1 bytes: the link is not open"));

        peer.echo = true;
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QVERIFY(link->write("y"));
        QTRY_COMPARE_WITH_TIMEOUT(rec.received.right(1), QByteArray("y"), kWaitMs);
    }

    // The peer resets the connection (SO_LINGER 0: RST instead of FIN).
    void peerResets()
    {
        Peer peer;
        peer.echo = false;
        auto link = makeLink(peer.url());
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(peer.last, kWaitMs);
        const linger hard{1, 0};
        QCOMPARE(::setsockopt(int(peer.last->socketDescriptor()), SOL_SOCKET, SO_LINGER, &hard, sizeof hard), 0);
        peer.last->abort();
        QTRY_COMPARE_WITH_TIMEOUT(rec.closed, 1, kWaitMs);
        QCOMPARE(link->state(), Link::State::Closed);
        QVERIFY(!rec.errors.isEmpty());
        // The link reads its descriptor itself, so a reset (ECONNRESET) is told from an orderly
        // close, with the link, the address and the operating system's words.
        QCOMPARE(rec.errors.last().kind, LinkError::Kind::Closed);
        QCOMPARE(rec.lastMessage(), peer.url() + QStringLiteral(": 127.0.0.1:%1 reset the connection (connection reset by peer)").arg(peer.port()));
    }

    void refused()
    {
        const quint16 port = closedPort();
        const QString url = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
        auto link = makeLink(url);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Refused);
        QCOMPARE(rec.lastMessage(), url + QStringLiteral(": connection refused by 127.0.0.1:%1: the host answered, but nothing "
                                                         "listens on port %1 (connection refused)")
                                              .arg(port));
        QCOMPARE(link->lastError().message, rec.lastMessage());
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.opened, 0);
        QCOMPARE(rec.closed, 0); // never open: only the error

        // The same link connects once something listens (reconnect on the next request).
        QTcpServer server;
        if (!server.listen(QHostAddress::LocalHost, port))
            QSKIP("the port was taken meanwhile");
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
    }

    // RFC 2606 reserves .invalid: the name never resolves.
    void unknownHost()
    {
        const QString url = QStringLiteral("tcp://mbscope-test.invalid:502?connect_timeout=60000ms");
        auto link = makeLink(url);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, 60000);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::NotFound);
        QVERIFY2(rec.lastMessage().startsWith(url + QStringLiteral(": host 'mbscope-test.invalid' not found (")),
                 qPrintable(rec.lastMessage()));
        QCOMPARE(link->state(), Link::State::Closed);
    }

    // A listening socket whose accept queue is full drops new SYNs (Linux: backlog 0 holds one
    // connection), so the connect neither succeeds nor fails: the connect timeout decides.
    void connectTimeout()
    {
        const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
        QVERIFY(listener >= 0);
        auto closeListener = qScopeGuard([&] { ::close(listener); });
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        QCOMPARE(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address), 0);
        QCOMPARE(::listen(listener, 0), 0);
        socklen_t length = sizeof address;
        QCOMPARE(::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length), 0);
        const quint16 port = ntohs(address.sin_port);
        // Fill the accept queue (never accepted).
        QTcpSocket fillers[2];
        for (QTcpSocket &filler : fillers)
            filler.connectToHost(QHostAddress::LocalHost, port);
        QTRY_COMPARE_WITH_TIMEOUT(fillers[0].state(), QAbstractSocket::ConnectedState, kWaitMs);

        const QString url = QStringLiteral("tcp://127.0.0.1:%1?connect_timeout=300ms").arg(port);
        auto link = makeLink(url);
        Recorder rec(link.get());
        link->open();
        QTRY_VERIFY_WITH_TIMEOUT(rec.opened + rec.errors.size() > 0, kWaitMs);
        if (rec.opened > 0)
            QSKIP("the kernel completed a connection past a full accept queue: no deterministic connect timeout here");
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Timeout);
        QCOMPARE(rec.lastMessage(), url + QStringLiteral(": no connection to 127.0.0.1:%1 within 300 ms (connect timeout): "
                                                         "the host did not answer")
                                              .arg(port));
        QCOMPARE(link->state(), Link::State::Closed);
    }

    // The engine runs links in its own thread: a link moved there takes its timer and socket
    // along, and works with calls queued to it while its signals reach this thread.
    void inWorkerThread()
    {
        Peer peer;
        QThread worker;
        worker.start();
        auto cleanup = qScopeGuard([&] {
            worker.quit();
            worker.wait();
        });
        Link *link = makeLink(peer.url()).release();
        Recorder rec(link);
        link->moveToThread(&worker);
        connect(&worker, &QThread::finished, link, &QObject::deleteLater);
        for (QObject *child : link->findChildren<QObject *>())
            QCOMPARE(child->thread(), &worker);
        QMetaObject::invokeMethod(link, [link] { link->open(); });
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        for (QObject *child : link->findChildren<QObject *>())
            QCOMPARE(child->thread(), &worker); // the socket made at open() too
        QMetaObject::invokeMethod(link, [link] { link->write("threaded"); });
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, QByteArray("threaded"), kWaitMs);
        QCOMPARE(rec.writtenNs.size(), 1);
        QMetaObject::invokeMethod(link, [link] { link->close(); });
        QTRY_COMPARE_WITH_TIMEOUT(rec.closed, 1, kWaitMs);
        QVERIFY(rec.errors.isEmpty());
    }

    // Deleting a link while a connection is open or opening is clean.
    void destroyWhileBusy()
    {
        Peer peer;
        auto opening = makeLink(peer.url());
        opening->open();
        opening.reset();
        auto open = makeLink(peer.url());
        Recorder rec(open.get());
        open->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QVERIFY(open->write("bye"));
        open.reset();
        QTRY_COMPARE_WITH_TIMEOUT(peer.disconnected, peer.accepted, kWaitMs);
    }
};

QTEST_GUILESS_MAIN(TestTcpLink)
#include "tst_tcplink.moc"
