// The transaction engine against pymodbus 3.0 (tests/peers/pymodbus_server.py), over every link
// pymodbus serves: tcp://, udp://, rtu-tcp:// and ascii-tcp:// on 127.0.0.1, and rtu:// and
// ascii:// on socat pty pairs. Every function code the peer answers is sent, and the values that
// come back are checked against the data map of tests/peers/peer_datamap.h (writes are read back).
// One peer and one engine per link, started on first use and stopped at the end.
#include "engineharness.h"
#include "peerprocess.h"

#include "engine/transactionengine.h"

#include <QtTest/QTest>

#include <map>
#include <memory>

using namespace mbscope;
using namespace mbscope::testpeers;

namespace {

const QStringList kLinks = {QStringLiteral("tcp"), QStringLiteral("udp"), QStringLiteral("rtu-tcp"),
                            QStringLiteral("ascii-tcp"), QStringLiteral("rtu"), QStringLiteral("ascii")};

bool isSerial(const QString &link)
{
    return link == QLatin1String("rtu") || link == QLatin1String("ascii");
}

struct Case {
    const char *name;
    const char *request;       // PDU, hex
    QByteArray expected;       // exact answer PDU; empty: only the status is checked
    const char *contains;      // the answer must contain these bytes (hex), or nullptr
    TransactionStatus status;
    int exceptionCode;
    const char *follow;        // a second request (a read-back), or nullptr
    QByteArray followExpected;
};

QList<Case> cases()
{
    using S = TransactionStatus;
    return {
        {"01 read coils 0x0000 x20", "01 0000 0014", expectedReadBits(0x01, 0, 20), nullptr, S::Ok, 0, nullptr, {}},
        {"01 read coils 0x0101 x37", "01 0101 0025", expectedReadBits(0x01, 0x101, 37), nullptr, S::Ok, 0, nullptr, {}},
        {"02 read discrete inputs 0x0007 x13", "02 0007 000D", expectedReadBits(0x02, 7, 13), nullptr, S::Ok, 0, nullptr, {}},
        {"03 read holding registers 0x0000 x10", "03 0000 000A", expectedReadRegisters(0x03, 0, 10), nullptr, S::Ok, 0,
         nullptr, {}},
        {"03 read holding registers 0x2693 x125 (table end)", "03 2693 007D", expectedReadRegisters(0x03, 0x2693, 125),
         nullptr, S::Ok, 0, nullptr, {}},
        {"04 read input registers 0x0064 x8", "04 0064 0008", expectedReadRegisters(0x04, 100, 8), nullptr, S::Ok, 0,
         nullptr, {}},
        {"05 write single coil 0x0201 ON", "05 0201 FF00", hex("05 0201 FF00"), nullptr, S::Ok, 0, "01 0201 0001",
         hex("01 01 01")},
        {"06 write single register 0x0300 0xBEEF", "06 0300 BEEF", hex("06 0300 BEEF"), nullptr, S::Ok, 0,
         "03 0300 0001", hex("03 02 BEEF")},
        {"0F write multiple coils 0x0400 x10", "0F 0400 000A 02 4D 03", hex("0F 0400 000A"), nullptr, S::Ok, 0,
         "01 0400 000A", hex("01 02 4D 03")},
        {"10 write multiple registers 0x0500 x3", "10 0500 0003 06 0001 8000 FFFF", hex("10 0500 0003"), nullptr, S::Ok,
         0, "03 0500 0003", hex("03 06 0001 8000 FFFF")},
        // hr(0x600) = 1000 + 3 * 1536 = 0x15E8; (0x15E8 AND 0xF0F0) OR (0x0005 AND NOT 0xF0F0) = 0x10E5 (V1.1b3 6.16)
        {"16 mask write register 0x0600", "16 0600 F0F0 0005", hex("16 0600 F0F0 0005"), nullptr, S::Ok, 0,
         "03 0600 0001", hex("03 02 10E5")},
        // The write happens before the read (V1.1b3 6.17): the answer holds hr(0x700) = 0x18E8, then
        // the written values.
        {"17 read/write multiple registers 0x0700", "17 0700 0003 0701 0002 04 1111 2222",
         hex("17 06 18E8 1111 2222"), nullptr, S::Ok, 0, nullptr, {}},
        {"08/00 return query data", "08 0000 A55A", hex("08 0000 A55A"), nullptr, S::Ok, 0, nullptr, {}},
        {"2B/0E read device identification basic", "2B 0E 01 00", {}, "2B0E01", S::Ok, 0, nullptr, {}},
        {"2B/0E vendor name", "2B 0E 04 00", {}, "6D6273636F7065207465737473" /* "mbscope tests" */, S::Ok, 0,
         nullptr, {}},
        {"07 read exception status", "07", {}, "07", S::Ok, 0, nullptr, {}},
        {"0B get comm event counter", "0B", {}, "0B", S::Ok, 0, nullptr, {}},
        {"0C get comm event log", "0C", {}, "0C", S::Ok, 0, nullptr, {}},
        {"11 report server id", "11", {}, "6D6273636F7065207465737473", S::Ok, 0, nullptr, {}},
        // pymodbus 3.0 answers every FIFO read with an empty queue (file_message.py: "TODO").
        {"18 read FIFO queue", "18 0010", hex("18 0002 0000"), nullptr, S::Ok, 0, nullptr, {}},
        {"03 past the table end: exception 02", "03 270F 0002", hex("83 02"), nullptr, S::Exception, 2, nullptr, {}},
        {"04 quantity 0: exception 03", "04 0000 0000", hex("84 03"), nullptr, S::Exception, 3, nullptr, {}},
    };
}

} // namespace

class TestEnginePymodbus : public QObject
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
    QString m_skip;

    // The peer and engine for a link, started on first use; nullptr with the reason on failure.
    Target *target(const QString &link, QString *error);
    std::optional<Transaction> exchange(Target *t, const QByteArray &pdu, quint8 unit = 1, int timeoutMs = 3000,
                                        QByteArray *sent = nullptr);

private slots:
    void initTestCase();
    void cleanupTestCase();
    void functionCodes_data();
    void functionCodes();
    void otherUnitTimesOutThenNextIsOk_data();
    void otherUnitTimesOutThenNextIsOk();
    void broadcastActsWithoutAnswer_data();
    void broadcastActsWithoutAnswer();
    void pollCounts_data();
    void pollCounts();
};

TestEnginePymodbus::Target *TestEnginePymodbus::target(const QString &link, QString *error)
{
    auto found = m_targets.find(link);
    if (found != m_targets.end())
        return &found->second;
    Target t;
    QStringList args{peersDir() + QStringLiteral("/pymodbus_server.py"), link};
    if (isSerial(link)) {
        t.pty = std::make_unique<PtyPair>();
        if (!t.pty->start()) {
            *error = t.pty->error();
            return nullptr;
        }
        args << QStringLiteral("--device") << t.pty->peerEnd();
    }
    if (link != QLatin1String("tcp") && link != QLatin1String("udp"))
        args << QStringLiteral("--broadcast"); // unit 0 is a broadcast on the serial framings only
    t.peer = std::make_unique<PeerProcess>();
    if (!t.peer->start(systemPython(), args)) {
        *error = t.peer->error();
        return nullptr;
    }
    t.url = isSerial(link) ? serialTarget(link, t.pty->ourEnd()) : networkTarget(link, t.peer->port());
    t.engine = std::make_unique<TransactionEngine>();
    t.engine->setTarget(t.url);
    return &m_targets.emplace(link, std::move(t)).first->second;
}

std::optional<Transaction> TestEnginePymodbus::exchange(Target *t, const QByteArray &pdu, quint8 unit, int timeoutMs,
                                                        QByteArray *sent)
{
    const RequestItem item = request(t->url, pdu, unit, t->nextTransactionId++, timeoutMs);
    if (sent)
        *sent = item.bytes;
    return t->engine->sendAndWait(item, timeoutMs + 5000);
}

void TestEnginePymodbus::initTestCase()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    if (!socatAvailable(&why))
        m_skip = why; // serial links only
}

void TestEnginePymodbus::cleanupTestCase()
{
    m_targets.clear(); // engines close their links, then peers and pty pairs stop
}

void TestEnginePymodbus::functionCodes_data()
{
    QTest::addColumn<QString>("link");
    QTest::addColumn<int>("index");
    const QList<Case> all = cases();
    for (const QString &link : kLinks) {
        for (qsizetype i = 0; i < all.size(); ++i)
            QTest::addRow("%s: %s", qPrintable(link), all.at(i).name) << link << int(i);
    }
}

void TestEnginePymodbus::functionCodes()
{
    QFETCH(QString, link);
    QFETCH(int, index);
    if (isSerial(link) && !m_skip.isEmpty())
        QSKIP(qPrintable(m_skip));
    const Case c = cases().at(index);
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));

    QByteArray sent;
    const std::optional<Transaction> tr = exchange(t, hex(c.request), 1, 3000, &sent);
    QVERIFY2(tr, "the engine recorded nothing");
    QVERIFY2(tr->status == c.status, qPrintable(describe(tr)));
    QCOMPARE(int(tr->exceptionCode), c.exceptionCode);
    QCOMPARE(tr->request.toHex(' '), sent.toHex(' ')); // sent exactly as given
    const QByteArray pdu = responsePdu(*tr, t->url.framing());
    if (!c.expected.isEmpty())
        QCOMPARE(pdu.toHex(' '), c.expected.toHex(' '));
    if (c.contains)
        QVERIFY2(pdu.contains(hex(c.contains)), qPrintable(QString::fromLatin1(pdu.toHex(' '))));
    // Timestamps: written, then the first byte of the answer, then its last; all from one clock.
    QVERIFY(tr->sentNs > 0);
    QVERIFY2(tr->firstByteNs >= tr->sentNs, qPrintable(describe(tr)));
    QVERIFY(tr->doneNs >= tr->firstByteNs);
    QVERIFY(tr->latencyNs() >= 0);

    if (c.follow) {
        const std::optional<Transaction> back = exchange(t, hex(c.follow));
        QVERIFY2(back && back->isOk(), qPrintable(describe(back)));
        QCOMPARE(responsePdu(*back, t->url.framing()).toHex(' '), c.followExpected.toHex(' '));
    }
}

void TestEnginePymodbus::otherUnitTimesOutThenNextIsOk_data()
{
    QTest::addColumn<QString>("link");
    for (const QString &link : kLinks)
        QTest::newRow(qPrintable(link)) << link;
}

void TestEnginePymodbus::otherUnitTimesOutThenNextIsOk()
{
    // pymodbus ignores requests for units it does not serve, on every framing.
    QFETCH(QString, link);
    if (isSerial(link) && !m_skip.isEmpty())
        QSKIP(qPrintable(m_skip));
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));
    const std::optional<Transaction> silent = exchange(t, hex("03 0000 0001"), 7, 300);
    QVERIFY2(silent && silent->status == TransactionStatus::Timeout, qPrintable(describe(silent)));
    QVERIFY(silent->response.isEmpty());
    QCOMPARE(silent->latencyNs(), qint64(-1));
    const std::optional<Transaction> ok = exchange(t, hex("03 0001 0002"));
    QVERIFY2(ok && ok->isOk(), qPrintable(describe(ok)));
    QCOMPARE(responsePdu(*ok, t->url.framing()), expectedReadRegisters(0x03, 1, 2));
}

void TestEnginePymodbus::broadcastActsWithoutAnswer_data()
{
    QTest::addColumn<QString>("link");
    for (const char *link : {"rtu-tcp", "rtu", "ascii"})
        QTest::newRow(link) << QString::fromLatin1(link);
}

void TestEnginePymodbus::broadcastActsWithoutAnswer()
{
    // Unit 0 on a serial framing: every server acts, none answers (Serial Line V1.02, 2.1).
    QFETCH(QString, link);
    if (isSerial(link) && !m_skip.isEmpty())
        QSKIP(qPrintable(m_skip));
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));
    const std::optional<Transaction> sent = exchange(t, hex("06 0800 1234"), 0);
    QVERIFY2(sent && sent->status == TransactionStatus::Broadcast, qPrintable(describe(sent)));
    QVERIFY(sent->response.isEmpty());
    const std::optional<Transaction> back = exchange(t, hex("03 0800 0001"));
    QVERIFY2(back && back->isOk(), qPrintable(describe(back)));
    QCOMPARE(responsePdu(*back, t->url.framing()), hex("03 02 1234"));
}

void TestEnginePymodbus::pollCounts_data()
{
    QTest::addColumn<QString>("link");
    for (const QString &link : kLinks)
        QTest::newRow(qPrintable(link)) << link;
}

void TestEnginePymodbus::pollCounts()
{
    // "write bits then write words, 100 times" (the M221 lab), then read: 3 items x 50 cycles.
    QFETCH(QString, link);
    if (isSerial(link) && !m_skip.isEmpty())
        QSKIP(qPrintable(m_skip));
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));
    PollSettings settings;
    settings.items = {request(t->url, hex("0F 0900 0003 01 05"), 1, 0x100, 2000),
                      request(t->url, hex("10 0900 0002 04 0102 0304"), 1, 0x101, 2000),
                      request(t->url, hex("03 0900 0002"), 1, 0x102, 2000)};
    settings.items[0].name = QStringLiteral("write bits");
    settings.items[1].name = QStringLiteral("write words");
    settings.items[2].name = QStringLiteral("read words");
    settings.count = 50;
    settings.intervalNs = 0;
    EngineProbe probe(t->engine.get());
    t->engine->startPoll(settings);
    const std::optional<PollReport> report = t->engine->waitForFinished(120000);
    QVERIFY2(report, "the poll did not finish within 120 s");
    QCOMPARE(report->runs.size(), 1);
    const PollRun &run = report->runs.first();
    QVERIFY(probe.waitFor([&] { return probe.records().size() >= 150; }, 5000));
    for (const Transaction &tr : probe.records())
        QVERIFY2(tr.isOk(), qPrintable(describe(tr) + QStringLiteral("; engine counters: ") + describe(probe.counters())));
    QCOMPARE(run.cycles, quint64(50));
    QCOMPARE(run.statistics.overall().count(), quint64(150));
    QCOMPARE(run.statistics.overall().ok(), quint64(150));
    QCOMPARE(run.statistics.overall().failed(), quint64(0));
    for (int item = 0; item < 3; ++item) {
        QCOMPARE(run.statistics.item(item).count(), quint64(50));
        QCOMPARE(run.statistics.item(item).ok(), quint64(50));
    }
    QCOMPARE(run.counters.unsolicitedFrames, quint64(0));
    QCOMPARE(run.counters.skippedBytes, quint64(0));
    // Every read in the poll saw what the writes before it put there.
    int reads = 0;
    for (const Transaction &tr : probe.records()) {
        if (tr.item != 2)
            continue;
        ++reads;
        QCOMPARE(responsePdu(tr, t->url.framing()), hex("03 04 0102 0304"));
    }
    QCOMPARE(reads, 50);
}

QTEST_GUILESS_MAIN(TestEnginePymodbus)
#include "tst_engine_pymodbus.moc"
