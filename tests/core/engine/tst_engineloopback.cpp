// The engine over real sockets on 127.0.0.1 (TcpLink, UdpLink) against scripted peers that live
// in the test's thread: QTcpServer / QUdpSocket on ports the OS picks.

#include "enginetesting.h"

#include <QtCore/QPointer>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtNetwork/QUdpSocket>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

namespace {

// Length of the complete MBAP request at the start of buffer, or 0 while it is incomplete.
qsizetype mbapLength(const QByteArray &buffer)
{
    if (buffer.size() < 6)
        return 0;
    const qsizetype length = 6 + (quint8(buffer.at(4)) << 8 | quint8(buffer.at(5)));
    return buffer.size() >= length ? length : 0;
}

// A TCP peer: cuts requests out of each connection's stream with a length rule and answers them
// as the script says (delays from the moment the request was complete).
class TcpPeer : public QObject
{
public:
    TcpPeer(PeerScript script, std::function<qsizetype(const QByteArray &)> length = mbapLength)
        : m_script(std::move(script))
        , m_length(std::move(length))
    {
        QObject::connect(&m_server, &QTcpServer::newConnection, this, [this] { accept(); });
        if (!m_server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot listen on 127.0.0.1");
    }

    [[nodiscard]] QString url(const char *scheme = "tcp", const char *query = "") const
    {
        return QStringLiteral("%1://127.0.0.1:%2%3").arg(QLatin1String(scheme)).arg(m_server.serverPort()).arg(QLatin1String(query));
    }

    int connections = 0;
    int requests = 0;

private:
    void accept()
    {
        while (QTcpSocket *socket = m_server.nextPendingConnection()) {
            ++connections;
            socket->setParent(this);
            auto buffer = std::make_shared<QByteArray>();
            QObject::connect(socket, &QTcpSocket::readyRead, socket, [this, socket, buffer] {
                buffer->append(socket->readAll());
                while (const qsizetype n = m_length(*buffer)) {
                    const QByteArray request = buffer->left(n);
                    buffer->remove(0, n);
                    for (const Reply &reply : m_script(request, requests++))
                        schedule(socket, reply);
                }
            });
            QObject::connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        }
    }

    void schedule(QTcpSocket *socket, const Reply &reply)
    {
        QPointer<QTcpSocket> guarded(socket);
        QTimer::singleShot(reply.delayMs, Qt::PreciseTimer, this, [guarded, reply] {
            if (!guarded || guarded->state() != QAbstractSocket::ConnectedState)
                return;
            if (!reply.bytes.isEmpty()) {
                guarded->write(reply.bytes);
                guarded->flush();
            }
            if (reply.close)
                guarded->disconnectFromHost();
        });
    }

    QTcpServer m_server;
    PeerScript m_script;
    std::function<qsizetype(const QByteArray &)> m_length;
};

PeerScript mbapAnswers(const char *pduHex, int delayMs = 0)
{
    const QByteArray pdu = hex(pduHex);
    return [pdu, delayMs](const QByteArray &request, int) {
        const quint16 tid = quint16(quint8(request.at(0)) << 8 | quint8(request.at(1)));
        return QList<Reply>{Reply{delayMs, AduBuilder::mbap(pdu, quint8(request.at(6)), tid), false}};
    };
}

// An engine with the real links (Link::create) and collectors.
struct RealEngine {
    explicit RealEngine(const QString &url, const EngineOptions &options = {})
        : target(parseUrl(url))
    {
        engine.setTarget(target, options);
        QObject::connect(&engine, &TransactionEngine::transactionsFinished, &engine,
                         [this](const QList<Transaction> &batch) { records += batch; });
        QObject::connect(&engine, &TransactionEngine::progress, &engine, [this](const EngineProgress &p) { progress = p; });
    }
    [[nodiscard]] RequestItem item(const QByteArray &bytes, int timeoutMs = 3000) const
    {
        RequestItem i = RequestItem::forLink(bytes, target);
        i.timeoutMs = timeoutMs;
        return i;
    }
    LinkUrl target;
    TransactionEngine engine;
    QList<Transaction> records;
    EngineProgress progress;
};

void checkTimes(const Transaction &t)
{
    QVERIFY(t.sentNs > 0);
    QVERIFY(t.sentNs <= t.firstByteNs);
    QVERIFY(t.firstByteNs <= t.doneNs);
    QVERIFY(t.latencyNs() > 0);
}

} // namespace

class tst_EngineLoopback : public QObject
{
    Q_OBJECT

private slots:
    void tcpAnswer();
    void tcpClosesMidFrameThenReconnects();
    void tcpRefused();
    void tcpTimeoutThenLate();
    void tcpGarbageBeforeAnswer();
    void tcpPipeliningOutOfOrder();
    void tcpPoll();
    void rtuOverTcp();
    void delimitedOverTcp();
    void udpAnswer();
};

void tst_EngineLoopback::tcpAnswer()
{
    TcpPeer peer(mbapAnswers("0304000a000b"));
    RealEngine e(peer.url());
    const QByteArray request = mbap("0300000002", 0x4242, 1);
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(request));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    QCOMPARE(t->request, request);
    QCOMPARE(t->response, mbap("0304000a000b", 0x4242, 1));
    checkTimes(*t);
    QCOMPARE(peer.connections, 1);
}

void tst_EngineLoopback::tcpClosesMidFrameThenReconnects()
{
    TcpPeer peer([](const QByteArray &request, int index) {
        const QByteArray answer = mbapAnswer(request, "0304000a000b");
        if (index == 0)
            return QList<Reply>{Reply{0, answer.left(10), true}};
        return QList<Reply>{Reply{0, answer, false}};
    });
    RealEngine e(peer.url());
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(mbap("0300000002", 1, 1)));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::LinkError);
    QVERIFY2(t->problem.contains(QLatin1String("closed")), qPrintable(t->problem));
    QVERIFY2(t->problem.contains(peer.url()), qPrintable(t->problem));
    const std::optional<Transaction> next = e.engine.sendAndWait(e.item(mbap("0300000002", 2, 1)));
    QVERIFY(next.has_value());
    QVERIFY2(next->status == TransactionStatus::Ok, qPrintable(next->problem));
    QCOMPARE(peer.connections, 2);
    QVERIFY(QTest::qWaitFor([&] { return e.progress.counters.skippedBytes == 10; }, 5000));
}

void tst_EngineLoopback::tcpRefused()
{
    quint16 port = 0;
    {
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost, 0));
        port = closed.serverPort();
    }
    RealEngine e(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(mbap("0300000002")));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::LinkError);
    QVERIFY2(t->problem.contains(QLatin1String("refused")), qPrintable(t->problem));
    QVERIFY2(t->problem.contains(QString::number(port)), qPrintable(t->problem));
}

void tst_EngineLoopback::tcpTimeoutThenLate()
{
    TcpPeer peer([](const QByteArray &request, int index) {
        return QList<Reply>{Reply{index == 0 ? 500 : 0, mbapAnswer(request, "0304000a000b"), false}};
    });
    RealEngine e(peer.url());
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(mbap("0300000002", 1, 1), 100));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Timeout);
    QVERIFY(QTest::qWaitFor([&] { return e.records.size() == 2; }, 10000));
    QCOMPARE(e.records.at(1).status, TransactionStatus::Late);
    QCOMPARE(e.records.at(1).id, t->id);
    const std::optional<Transaction> next = e.engine.sendAndWait(e.item(mbap("0300000002", 2, 1)));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
    QCOMPARE(peer.connections, 1);
}

void tst_EngineLoopback::tcpGarbageBeforeAnswer()
{
    TcpPeer peer([](const QByteArray &request, int) {
        return QList<Reply>{Reply{0, hex("ffffffff") + mbapAnswer(request, "0304000a000b"), false}};
    });
    RealEngine e(peer.url());
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(mbap("0300000002", 1, 1)));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    QVERIFY(QTest::qWaitFor([&] { return e.progress.counters.skippedBytes == 4; }, 5000));
}

void tst_EngineLoopback::tcpPipeliningOutOfOrder()
{
    auto held = std::make_shared<QList<QByteArray>>();
    TcpPeer peer([held](const QByteArray &request, int) {
        held->append(request);
        QList<Reply> replies;
        if (held->size() == 4) {
            for (qsizetype i = 3; i >= 0; --i)
                replies.append(Reply{int(3 - i) * 5, mbapAnswer(held->at(i), "0304000a000b"), false});
            held->clear();
        }
        return replies;
    });
    EngineOptions options;
    options.pipelineDepth = 4;
    RealEngine e(peer.url(), options);
    QList<quint64> ids;
    for (int i = 0; i < 8; ++i)
        ids.append(e.engine.send(e.item(mbap("0300000002", 7, 1))));
    QVERIFY(QTest::qWaitFor([&] { return e.records.size() == 8; }, 20000));
    for (const Transaction &t : std::as_const(e.records)) {
        QVERIFY2(t.status == TransactionStatus::Ok, qPrintable(t.problem));
        QCOMPARE(t.response.left(2), t.request.left(2));
        checkTimes(t);
    }
    QCOMPARE(e.records.at(0).id, ids.at(3));
    QCOMPARE(e.records.at(3).id, ids.at(0));
    QCOMPARE(e.records.at(4).id, ids.at(7));
}

void tst_EngineLoopback::tcpPoll()
{
    TcpPeer peer([](const QByteArray &request, int) {
        const char *pdu = quint8(request.at(7)) == 0x0F ? "0F00000003" : "1000000002";
        return QList<Reply>{Reply{0, mbapAnswer(request, pdu), false}};
    });
    RealEngine e(peer.url());
    PollSettings poll;
    poll.items = {e.item(mbap("0F000000030105", 1, 1)), e.item(mbap("100000000204000a000b", 2, 1))};
    poll.items[0].name = QStringLiteral("write bits");
    poll.items[1].name = QStringLiteral("write words");
    poll.count = 100;
    e.engine.startPoll(poll);
    const std::optional<PollReport> report = e.engine.waitForFinished(60000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(100));
    QCOMPARE(run.statistics.overall().ok(), quint64(200));
    QCOMPARE(run.statistics.item(0).ok(), quint64(100));
    QCOMPARE(run.statistics.item(1).ok(), quint64(100));
    QVERIFY(run.statistics.overall().latency().minNs() > 0);
    QCOMPARE(e.records.size(), 200);
    QCOMPARE(peer.connections, 1);
}

void tst_EngineLoopback::rtuOverTcp()
{
    TcpPeer peer([](const QByteArray &, int) { return QList<Reply>{Reply{0, rtu("0304000a000b", 1), false}}; },
                 [](const QByteArray &buffer) { return buffer.size() >= 8 ? qsizetype(8) : qsizetype(0); });
    RealEngine e(peer.url("rtu-tcp"));
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(rtu("0300000002", 1)));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    checkTimes(*t);
}

void tst_EngineLoopback::delimitedOverTcp()
{
    TcpPeer peer([](const QByteArray &, int) { return QList<Reply>{Reply{0, QByteArray("$01 293 295 #"), false}}; },
                 [](const QByteArray &buffer) { return buffer.indexOf('#') + 1; });
    RealEngine e(peer.url("tcp", "?framing=delimited&start=24&end=23"));
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(QByteArray("$01R#")));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    QCOMPARE(t->response, QByteArray("$01 293 295 #"));
}

void tst_EngineLoopback::udpAnswer()
{
    QUdpSocket server;
    QVERIFY(server.bind(QHostAddress::LocalHost, 0));
    QObject::connect(&server, &QUdpSocket::readyRead, &server, [&server] {
        while (server.hasPendingDatagrams()) {
            QByteArray datagram(int(server.pendingDatagramSize()), Qt::Uninitialized);
            QHostAddress from;
            quint16 port = 0;
            server.readDatagram(datagram.data(), datagram.size(), &from, &port);
            // Garbage in a datagram of its own, then the answer.
            server.writeDatagram(hex("0102"), from, port);
            server.writeDatagram(mbapAnswer(datagram, "0304000a000b"), from, port);
        }
    });
    RealEngine e(QStringLiteral("udp://127.0.0.1:%1").arg(server.localPort()));
    const std::optional<Transaction> t = e.engine.sendAndWait(e.item(mbap("0300000002", 9, 1)));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    checkTimes(*t);
    QVERIFY(QTest::qWaitFor([&] { return e.progress.counters.skippedBytes == 2; }, 5000));
}

QTEST_GUILESS_MAIN(tst_EngineLoopback)
#include "tst_engineloopback.moc"
