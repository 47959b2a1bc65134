// SimTcpStream, the simulator's plain TCP connection on its descriptor: bytes the kernel cannot
// take at once leave later in order, a close waits for them, the peer's end and a reset are seen,
// and a failed write never says disconnected() from inside write(). On a socketpair, whose buffers
// fill as a TCP connection's do when the client does not read.
#include "sim/simtcpstream.h"

#include <QtTest/QtTest>

#include <sys/socket.h>
#include <unistd.h>

using namespace mbscope;

namespace {

// A connected pair of non-blocking stream sockets; [0] for the stream, [1] the test's peer.
bool makePair(int fds[2])
{
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0, fds) != 0)
        return false;
    return true;
}

// Reads what the peer end has now (non-blocking); *ended at its end of stream.
QByteArray drainPeer(int fd, bool *ended)
{
    QByteArray out;
    char buffer[65536];
    for (;;) {
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n > 0) {
            out.append(buffer, n);
            continue;
        }
        *ended = n == 0;
        return out;
    }
}

QByteArray pattern(int size)
{
    QByteArray bytes(size, Qt::Uninitialized);
    for (int i = 0; i < size; ++i)
        bytes[i] = char(i * 7 + i / 251);
    return bytes;
}

} // namespace

class TestSimTcpStream : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void readsWhatArrivesAndTheEnd();
    void writesInOrderWhenTheKernelIsFull();
    void closeWaitsForTheUnsent();
    void failedWriteSaysDisconnectedLater();
};

void TestSimTcpStream::readsWhatArrivesAndTheEnd()
{
    int fds[2];
    QVERIFY(makePair(fds));
    SimTcpStream stream(fds[0]);
    QSignalSpy ready(&stream, &SimTcpStream::readyRead);
    QCOMPARE(::send(fds[1], "\x00\x01\x00\x00\x00\x06\x01\x03\x00\x00\x00\x01", 12, 0), ssize_t(12));
    QTRY_VERIFY_WITH_TIMEOUT(ready.count() >= 1, 5000);
    bool ended = true;
    QCOMPARE(stream.readAll(&ended).toHex(' '), QByteArray("00 01 00 00 00 06 01 03 00 00 00 01"));
    QVERIFY(!ended);
    QVERIFY(stream.readAll(&ended).isEmpty()); // nothing more yet
    QVERIFY(!ended);
    ready.clear();
    ::close(fds[1]);
    QTRY_VERIFY_WITH_TIMEOUT(ready.count() >= 1, 5000);
    QVERIFY(stream.readAll(&ended).isEmpty());
    QVERIFY(ended);
}

void TestSimTcpStream::writesInOrderWhenTheKernelIsFull()
{
    int fds[2];
    QVERIFY(makePair(fds));
    SimTcpStream stream(fds[0]);
    // Far more than the socket buffers hold: most of it waits in the stream.
    const QByteArray sent = pattern(4 * 1024 * 1024);
    for (qsizetype at = 0; at < sent.size(); at += 1000)
        QVERIFY(stream.write(QByteArrayView(sent).sliced(at, std::min<qsizetype>(1000, sent.size() - at))));
    QByteArray received;
    bool ended = false;
    QElapsedTimer clock;
    clock.start();
    while (received.size() < sent.size() && clock.elapsed() < 20000) {
        received += drainPeer(fds[1], &ended);
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    QCOMPARE(received.size(), sent.size());
    QVERIFY(received == sent);
    QVERIFY(stream.isOpen());
    ::close(fds[1]);
}

void TestSimTcpStream::closeWaitsForTheUnsent()
{
    int fds[2];
    QVERIFY(makePair(fds));
    auto *stream = new SimTcpStream(fds[0]);
    QSignalSpy gone(stream, &SimTcpStream::disconnected);
    const QByteArray sent = pattern(2 * 1024 * 1024);
    QVERIFY(stream->write(sent));
    stream->closeAfterWrites();
    QCOMPARE(gone.count(), 0); // bytes still wait: not closed yet
    QByteArray received;
    bool ended = false;
    QElapsedTimer clock;
    clock.start();
    while (!ended && clock.elapsed() < 20000) {
        received += drainPeer(fds[1], &ended);
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    QVERIFY(ended);
    QVERIFY(received == sent);
    QCOMPARE(gone.count(), 1);
    QVERIFY(!stream->isOpen());
    delete stream;
    ::close(fds[1]);
}

void TestSimTcpStream::failedWriteSaysDisconnectedLater()
{
    int fds[2];
    QVERIFY(makePair(fds));
    SimTcpStream stream(fds[0]);
    QSignalSpy gone(&stream, &SimTcpStream::disconnected);
    ::close(fds[1]);
    // The peer is gone: the send fails (EPIPE, no SIGPIPE) and the stream closes.
    QVERIFY(!stream.write(QByteArray("\x00\x01", 2)));
    QVERIFY(!stream.isOpen());
    QCOMPARE(gone.count(), 0); // not inside write()
    QTRY_COMPARE_WITH_TIMEOUT(gone.count(), 1, 5000);
}

QTEST_GUILESS_MAIN(TestSimTcpStream)
#include "tst_simtcpstream.moc"
