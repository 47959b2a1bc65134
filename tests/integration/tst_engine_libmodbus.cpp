// The transaction engine against a server built on libmodbus 3.1 (tests/peers/libmodbus_server.c):
// MBAP over TCP on 127.0.0.1 and RTU on a socat pty pair. Every function code libmodbus's
// modbus_reply() serves (01-06, 0F, 10, 11, 16, 17) with values checked against
// tests/peers/peer_datamap.h, the codes it refuses, and what libmodbus does differently from
// pymodbus (it answers any unit on TCP, ignores 07). On TCP also pipelining: libmodbus answers
// requests in order, several in flight.
#include "engineharness.h"
#include "peerprocess.h"

#include "engine/transactionengine.h"

#include <QtTest/QTest>

#include <map>
#include <memory>

using namespace mbscope;
using namespace mbscope::testpeers;

namespace {

struct Case {
    const char *name;
    const char *request;  // PDU, hex
    QByteArray expected;  // exact answer PDU; empty: only the status (and contains) are checked
    const char *contains; // hex the answer must contain, or nullptr
    TransactionStatus status;
    int exceptionCode;
    const char *follow;   // a read-back, or nullptr
    QByteArray followExpected;
    // libmodbus's RTU backend sizes a request by its function code; one it does not know is never
    // delimited, so it is dropped unanswered (TCP has the MBAP length and answers exception 01).
    bool rtuUnanswered = false;
};

QList<Case> cases()
{
    using S = TransactionStatus;
    return {
        {"01 read coils 0x0003 x70", "01 0003 0046", expectedReadBits(0x01, 3, 70), nullptr, S::Ok, 0, nullptr, {}},
        {"02 read discrete inputs 0x0000 x8", "02 0000 0008", expectedReadBits(0x02, 0, 8), nullptr, S::Ok, 0, nullptr, {}},
        {"03 read holding registers 0x0079 x22", "03 0079 0016", expectedReadRegisters(0x03, 0x79, 22), nullptr, S::Ok, 0,
         nullptr, {}},
        {"03 read holding registers 0x0000 x125", "03 0000 007D", expectedReadRegisters(0x03, 0, 125), nullptr, S::Ok, 0,
         nullptr, {}},
        {"04 read input registers 0x270E x2 (table end)", "04 270E 0002", expectedReadRegisters(0x04, 0x270E, 2), nullptr,
         S::Ok, 0, nullptr, {}},
        {"05 write single coil 0x0100 ON", "05 0100 FF00", hex("05 0100 FF00"), nullptr, S::Ok, 0, "01 00FF 0003",
         hex("01 01 03")}, // 0xFF ON (divisible by 3), 0x100 now ON, 0x101 OFF
        {"06 write single register 0x0200 0x0000", "06 0200 0000", hex("06 0200 0000"), nullptr, S::Ok, 0,
         "03 0200 0002", hex("03 04 0000 09EB")}, // hr(0x201) = 1000 + 3 * 513 = 0x09EB
        {"0F write multiple coils 0x0300 x3", "0F 0300 0003 01 06", hex("0F 0300 0003"), nullptr, S::Ok, 0,
         "01 0300 0003", hex("01 01 06")},
        {"10 write multiple registers 0x0400 x2", "10 0400 0002 04 CAFE F00D", hex("10 0400 0002"), nullptr, S::Ok, 0,
         "03 0400 0002", hex("03 04 CAFE F00D")},
        // hr(0x500) = 1000 + 3 * 1280 = 0x12E8; (0x12E8 AND 0x00FF) OR (0x5500 AND NOT 0x00FF) = 0x55E8
        {"16 mask write register 0x0500", "16 0500 00FF 5500", hex("16 0500 00FF 5500"), nullptr, S::Ok, 0,
         "03 0500 0001", hex("03 02 55E8")},
        // Write first, then read (V1.1b3 6.17): hr(0x600) = 0x15E8, then the written 0x0102.
        {"17 read/write multiple registers 0x0600", "17 0600 0002 0601 0001 02 0102", hex("17 04 15E8 0102"), nullptr,
         S::Ok, 0, nullptr, {}},
        // libmodbus: byte count, its slave id, run indicator ON, then "LMB" and its version.
        {"11 report server id", "11", {}, "FF4C4D42", S::Ok, 0, nullptr, {}},
        {"03 past the table end: exception 02", "03 2710 0001", hex("83 02"), nullptr, S::Exception, 2, nullptr, {}},
        {"03 quantity 126: exception 03", "03 0000 007E", hex("83 03"), nullptr, S::Exception, 3, nullptr, {}},
        {"08/00 not served: exception 01", "08 0000 1234", hex("88 01"), nullptr, S::Exception, 1, nullptr, {}, true},
        {"2B/0E not served: exception 01", "2B 0E 01 00", hex("AB 01"), nullptr, S::Exception, 1, nullptr, {}, true},
        // libmodbus 3.1.6's modbus_reply() returns ENOPROTOOPT for 07 and sends nothing.
        {"07 not answered at all", "07", {}, nullptr, S::Timeout, 0, nullptr, {}},
    };
}

} // namespace

class TestEngineLibmodbus : public QObject
{
    Q_OBJECT

    struct Target {
        std::unique_ptr<PtyPair> pty;
        std::unique_ptr<PeerProcess> peer;
        std::unique_ptr<TransactionEngine> engine;
        LinkUrl url;
        quint16 nextTransactionId = 1;
    };
    std::map<QString, Target> m_targets;
    QString m_skipSerial;

    Target *target(const QString &link, QString *error);
    std::optional<Transaction> exchange(Target *t, const QByteArray &pdu, quint8 unit = 1, int timeoutMs = 2000);

private slots:
    void initTestCase();
    void cleanupTestCase();
    void functionCodes_data();
    void functionCodes();
    void units();
    void rtuBroadcast();
    void pipelinedPoll_data();
    void pipelinedPoll();
};

TestEngineLibmodbus::Target *TestEngineLibmodbus::target(const QString &link, QString *error)
{
    auto found = m_targets.find(link);
    if (found != m_targets.end())
        return &found->second;
    Target t;
    QStringList args{link};
    if (link == QLatin1String("rtu")) {
        t.pty = std::make_unique<PtyPair>();
        if (!t.pty->start()) {
            *error = t.pty->error();
            return nullptr;
        }
        args << QStringLiteral("--device") << t.pty->peerEnd();
    }
    t.peer = std::make_unique<PeerProcess>();
    if (!t.peer->start(libmodbusServerPath(), args)) {
        *error = t.peer->error();
        return nullptr;
    }
    t.url = link == QLatin1String("rtu") ? serialTarget(link, t.pty->ourEnd()) : networkTarget(link, t.peer->port());
    t.engine = std::make_unique<TransactionEngine>();
    t.engine->setTarget(t.url);
    return &m_targets.emplace(link, std::move(t)).first->second;
}

std::optional<Transaction> TestEngineLibmodbus::exchange(Target *t, const QByteArray &pdu, quint8 unit, int timeoutMs)
{
    const RequestItem item = request(t->url, pdu, unit, t->nextTransactionId++, timeoutMs);
    return t->engine->sendAndWait(item, timeoutMs + 5000);
}

void TestEngineLibmodbus::initTestCase()
{
    QString why;
    if (!libmodbusPeersAvailable(&why))
        QSKIP(qPrintable(why));
    if (!socatAvailable(&why))
        m_skipSerial = why;
}

void TestEngineLibmodbus::cleanupTestCase()
{
    m_targets.clear();
}

void TestEngineLibmodbus::functionCodes_data()
{
    QTest::addColumn<QString>("link");
    QTest::addColumn<int>("index");
    const QList<Case> all = cases();
    for (const char *link : {"tcp", "rtu"}) {
        for (qsizetype i = 0; i < all.size(); ++i)
            QTest::addRow("%s: %s", link, all.at(i).name) << QString::fromLatin1(link) << int(i);
    }
}

void TestEngineLibmodbus::functionCodes()
{
    QFETCH(QString, link);
    QFETCH(int, index);
    if (link == QLatin1String("rtu") && !m_skipSerial.isEmpty())
        QSKIP(qPrintable(m_skipSerial));
    Case c = cases().at(index);
    if (link == QLatin1String("rtu") && c.rtuUnanswered) {
        c.status = TransactionStatus::Timeout;
        c.exceptionCode = 0;
        c.expected.clear();
    }
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));

    const int timeoutMs = c.status == TransactionStatus::Timeout ? 300 : 2000;
    const std::optional<Transaction> tr = exchange(t, hex(c.request), 1, timeoutMs);
    QVERIFY2(tr && tr->status == c.status, qPrintable(describe(tr)));
    QCOMPARE(int(tr->exceptionCode), c.exceptionCode);
    const QByteArray pdu = responsePdu(*tr, t->url.framing());
    if (!c.expected.isEmpty())
        QCOMPARE(pdu.toHex(' '), c.expected.toHex(' '));
    if (c.contains)
        QVERIFY2(pdu.contains(hex(c.contains)), qPrintable(QString::fromLatin1(pdu.toHex(' '))));
    if (c.status != TransactionStatus::Timeout) {
        QVERIFY(tr->sentNs > 0 && tr->firstByteNs >= tr->sentNs && tr->doneNs >= tr->firstByteNs);
    }
    if (c.follow) {
        const std::optional<Transaction> back = exchange(t, hex(c.follow));
        QVERIFY2(back && back->isOk(), qPrintable(describe(back)));
        QCOMPARE(responsePdu(*back, t->url.framing()).toHex(' '), c.followExpected.toHex(' '));
    }
}

void TestEngineLibmodbus::units()
{
    // libmodbus's TCP backend answers every unit id (its filter is for RTU); its RTU backend only
    // its own (unit 1 here), so another unit times out and the next request is answered.
    QString error;
    Target *tcp = target(QStringLiteral("tcp"), &error);
    QVERIFY2(tcp, qPrintable(error));
    for (quint8 unit : {quint8(0), quint8(7), quint8(255)}) {
        const std::optional<Transaction> tr = exchange(tcp, hex("03 0000 0001"), unit);
        QVERIFY2(tr && tr->isOk(), qPrintable(describe(tr)));
        QCOMPARE(quint8(tr->response.at(6)), unit); // the MBAP unit id is echoed
    }
    if (!m_skipSerial.isEmpty())
        QSKIP(qPrintable(m_skipSerial));
    Target *rtu = target(QStringLiteral("rtu"), &error);
    QVERIFY2(rtu, qPrintable(error));
    const std::optional<Transaction> silent = exchange(rtu, hex("03 0000 0001"), 7, 300);
    QVERIFY2(silent && silent->status == TransactionStatus::Timeout, qPrintable(describe(silent)));
    // libmodbus then ignores the next frame on the line, taking it for unit 7's answer (its RTU
    // backend's confirmation_to_ignore, right on a multi-drop bus): the first attempt of the next
    // request goes unanswered and its retry is answered.
    RequestItem next = request(rtu->url, hex("03 0000 0001"), 1, 0, 300);
    next.retries = 2;
    const std::optional<Transaction> ok = rtu->engine->sendAndWait(next, 10000);
    QVERIFY2(ok && ok->isOk(), qPrintable(describe(ok)));
    QVERIFY2(ok->attempt >= 1, "libmodbus answered the frame after another unit's request at once");
    QCOMPARE(responsePdu(*ok, rtu->url.framing()), expectedReadRegisters(0x03, 0, 1));
}

void TestEngineLibmodbus::rtuBroadcast()
{
    if (!m_skipSerial.isEmpty())
        QSKIP(qPrintable(m_skipSerial));
    QString error;
    Target *t = target(QStringLiteral("rtu"), &error);
    QVERIFY2(t, qPrintable(error));
    const std::optional<Transaction> sent = exchange(t, hex("10 0A00 0002 04 0011 0022"), 0);
    QVERIFY2(sent && sent->status == TransactionStatus::Broadcast, qPrintable(describe(sent)));
    const std::optional<Transaction> back = exchange(t, hex("03 0A00 0002"));
    QVERIFY2(back && back->isOk(), qPrintable(describe(back)));
    QCOMPARE(responsePdu(*back, t->url.framing()), hex("03 04 0011 0022"));
}

void TestEngineLibmodbus::pipelinedPoll_data()
{
    QTest::addColumn<int>("depth");
    for (int depth : {1, 4, 8})
        QTest::addRow("depth %d", depth) << depth;
}

void TestEngineLibmodbus::pipelinedPoll()
{
    // Requests in flight at once, told apart by the transaction ids the engine gives them
    // (Messaging on TCP/IP V1.0b, 4.2); libmodbus answers them one after the other.
    QFETCH(int, depth);
    QString error;
    Target *t = target(QStringLiteral("tcp"), &error);
    QVERIFY2(t, qPrintable(error));
    TransactionEngine engine; // an engine of its own: the pipeline depth is per target
    EngineOptions options;
    options.pipelineDepth = depth;
    engine.setTarget(t->url, options);
    EngineProbe probe(&engine);
    PollSettings settings;
    settings.items = {request(t->url, hex("03 0010 0004"), 1, 0x0101, 2000), request(t->url, hex("04 0020 0003"), 1, 0x0102, 2000)};
    settings.count = 300;
    engine.startPoll(settings);
    const std::optional<PollReport> report = engine.waitForFinished(120000);
    QVERIFY2(report && report->runs.size() == 1, "the poll did not finish within 120 s");
    const PollRun &run = report->runs.first();
    QVERIFY(probe.waitFor([&] { return probe.records().size() >= 600; }, 5000));
    for (const Transaction &tr : probe.records()) {
        QVERIFY2(tr.isOk(), qPrintable(describe(tr) + QStringLiteral("; ") + describe(probe.counters())));
        QCOMPARE(tr.transactionIdRewritten, depth > 1 && tr.request.left(2) != (tr.item == 0 ? hex("0101") : hex("0102")));
        QCOMPARE(tr.response.left(2), tr.request.left(2)); // each answer carries its request's id
        QCOMPARE(responsePdu(tr, Framing::Tcp),
                 tr.item == 0 ? expectedReadRegisters(0x03, 0x10, 4) : expectedReadRegisters(0x04, 0x20, 3));
    }
    QCOMPARE(run.statistics.overall().count(), quint64(600));
    QCOMPARE(run.statistics.overall().ok(), quint64(600));
    QCOMPARE(run.counters.unsolicitedFrames, quint64(0));
    QCOMPARE(run.cycles, quint64(300));
}

QTEST_GUILESS_MAIN(TestEngineLibmodbus)
#include "tst_engine_libmodbus.moc"
