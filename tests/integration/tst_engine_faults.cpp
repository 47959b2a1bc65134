// The transaction engine against a server that misbehaves on purpose (tests/peers/fault_server.py):
// each fault must end in the right category (the transaction's status, or the engine's counters
// for what came outside a transaction), nothing that arrived may go uncounted, and the next
// transaction must be correct again. Three links: tcp:// (MBAP), rtu-tcp:// (RTU over TCP, ends
// frames after EngineOptions::streamSilenceMs of quiet) and rtu:// on a pty that socat bridges to
// the RTU-over-TCP fault server (a serial line: frames end after t3.5, Serial Line V1.02 2.5.1.1).
#include "engineharness.h"
#include "peerprocess.h"

#include "engine/engineoptions.h"
#include "engine/transactionengine.h"

#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <map>
#include <utility>
#include <memory>

using namespace mbscope;
using namespace mbscope::testpeers;

namespace {

using S = TransactionStatus;

// The request every row sends: Read Holding Registers at 0x0010, 3 registers (11-byte RTU answer,
// 15-byte MBAP answer), and what it must read back (peer_datamap.h).
const QByteArray kRead = QByteArray::fromHex("0300100003");

struct Fault {
    const char *link;
    const char *command; // what follows "next " on the fault server's stdin
    int timeoutMs;
    S status;
    int exceptionCode;
};

// Counters a fault must move, and by how much (checked once the server says it is done).
struct Moves {
    int duplicates = 0;
    int late = 0;
    int skippedBytes = -1; // -1: not checked
    int connects = 0;
};

} // namespace

Q_DECLARE_METATYPE(mbscope::TransactionStatus)

class TestEngineFaults : public QObject
{
    Q_OBJECT

    struct Target {
        std::unique_ptr<PeerProcess> server;
        std::unique_ptr<QTemporaryDir> dir;
        std::unique_ptr<QProcess> bridge; // socat pty <-> tcp, serial rows only
        std::unique_ptr<TransactionEngine> engine;
        std::unique_ptr<EngineProbe> probe;
        LinkUrl url;
        quint16 nextTransactionId = 1;
        int requests = 0; // requests sent to the server (each one reported "SERVED n")
    };
    std::map<QString, Target> m_targets;
    Target *m_current = nullptr; // the row's target, for cleanup()

    Target *target(const QString &link, QString *error);
    std::optional<Transaction> exchange(Target *t, int timeoutMs, QByteArray *sent = nullptr);
    // Waits until the server has reported the last request sent as served.
    bool waitServed(Target *t, int timeoutMs = 10000);

private slots:
    void initTestCase();
    void cleanupTestCase();
    void cleanup();
    void fault_data();
    void fault();
};

TestEngineFaults::Target *TestEngineFaults::target(const QString &link, QString *error)
{
    auto found = m_targets.find(link);
    if (found != m_targets.end())
        return &found->second;
    Target t;
    const bool serial = link == QLatin1String("rtu");
    t.server = std::make_unique<PeerProcess>();
    if (!t.server->start(systemPython(), {peersDir() + QStringLiteral("/fault_server.py"),
                                          serial ? QStringLiteral("rtu-tcp") : link})) {
        *error = t.server->error();
        return nullptr;
    }
    if (serial) {
        // A pty whose other side is one TCP connection to the RTU-over-TCP fault server: what the
        // engine writes on the pty reaches the server, the server's bytes come out with the gaps
        // it made (socat forwards each read as it comes).
        t.dir = std::make_unique<QTemporaryDir>();
        const QString device = t.dir->filePath(QStringLiteral("faulty"));
        t.bridge = std::make_unique<QProcess>();
        t.bridge->setReadChannel(QProcess::StandardError);
        t.bridge->start(QStringLiteral("socat"), {QStringLiteral("-d"), QStringLiteral("-d"),
                                                  QStringLiteral("pty,raw,echo=0,link=") + device,
                                                  QStringLiteral("tcp:127.0.0.1:") + QString::number(t.server->port())});
        QByteArray log;
        for (int i = 0; i < 100 && !log.contains("starting data transfer loop"); ++i) {
            t.bridge->waitForReadyRead(100);
            log += t.bridge->readAllStandardError();
        }
        if (!log.contains("starting data transfer loop")) {
            *error = QStringLiteral("socat bridge did not start: ") + QString::fromLocal8Bit(log);
            return nullptr;
        }
        t.url = serialTarget(QStringLiteral("rtu"), device);
    } else {
        t.url = networkTarget(link, t.server->port());
    }
    t.engine = std::make_unique<TransactionEngine>();
    t.probe = std::make_unique<EngineProbe>(t.engine.get());
    EngineOptions options;
    options.streamSilenceMs = 50;
    t.engine->setTarget(t.url, options);
    Target *made = &m_targets.emplace(link, std::move(t)).first->second;
    // One good exchange first, so that rows start on an open link and count reconnections only.
    const std::optional<Transaction> first = exchange(made, 3000);
    if (!first || !first->isOk() || !waitServed(made)) {
        *error = QStringLiteral("the first exchange failed: ") + describe(first);
        m_targets.erase(link);
        return nullptr;
    }
    return made;
}

std::optional<Transaction> TestEngineFaults::exchange(Target *t, int timeoutMs, QByteArray *sent)
{
    const RequestItem item = request(t->url, kRead, 1, t->nextTransactionId++, timeoutMs);
    if (sent)
        *sent = item.bytes;
    ++t->requests;
    return t->engine->sendAndWait(item, timeoutMs + 5000);
}

bool TestEngineFaults::waitServed(Target *t, int timeoutMs)
{
    return t->server->waitForLine("SERVED " + QByteArray::number(t->requests) + ' ', timeoutMs);
}

void TestEngineFaults::initTestCase()
{
    QString why;
    if (!pymodbusAvailable(&why)) // the fault server needs only python3; pymodbus stands for Debian's python3
        QSKIP(qPrintable(why));
}

void TestEngineFaults::cleanupTestCase()
{
    for (auto &[link, t] : m_targets) {
        t.engine.reset();
        if (t.bridge) {
            t.bridge->terminate();
            if (!t.bridge->waitForFinished(3000))
                t.bridge->kill();
            t.bridge->waitForFinished(3000);
        }
    }
    m_targets.clear();
}

void TestEngineFaults::cleanup()
{
    // Whatever a row left behind (it may have stopped at its first failed check), the next row
    // starts on an open link with everything counted: one more good exchange, all served.
    Target *t = std::exchange(m_current, nullptr);
    if (!t)
        return;
    (void)exchange(t, 2000);
    (void)waitServed(t);
    (void)t->probe->waitFor([&] { return t->probe->counters().transactions == quint64(t->probe->records().size()); }, 5000);
}

void TestEngineFaults::fault_data()
{
    QTest::addColumn<QString>("link");
    QTest::addColumn<QString>("command");
    QTest::addColumn<int>("timeoutMs");
    QTest::addColumn<TransactionStatus>("status");
    QTest::addColumn<int>("exceptionCode");
    QTest::addColumn<int>("duplicates");
    QTest::addColumn<int>("late");
    QTest::addColumn<int>("skippedBytes");
    QTest::addColumn<int>("connects");

    // link, fault, timeout, status, exception, duplicates, late, skipped bytes (-1: any), reconnects
    auto row = [](const char *link, const char *command, int timeoutMs, S status, int exception, int duplicates,
                  int late, int skipped, int connects) {
        QTest::addRow("%s: %s", link, command) << QString::fromLatin1(link) << QString::fromLatin1(command) << timeoutMs
                                               << status << exception << duplicates << late << skipped << connects;
    };
    for (const char *link : {"tcp", "rtu-tcp", "rtu"}) {
        const bool mbap = QByteArray(link) == "tcp";
        const bool serial = QByteArray(link) == "rtu";
        row(link, "none", 2000, S::Ok, 0, 0, 0, 0, 0);
        row(link, "silent", 300, S::Timeout, 0, 0, 0, 0, 0);
        // Half an answer, then the server closes: the link error ends the transaction; the next
        // request opens the link again. (On the pty the bridge ends instead: serial rows skip it.)
        if (!serial)
            row(link, "close", 2000, S::LinkError, 0, 0, 0, -1, 1);
        // MBAP is delimited by its length field, so a slow answer is still whole.
        if (!serial)
            row(link, "trickle 10", 3000, S::Ok, 0, 0, 0, 0, 0);
        // Slower than the engine's end-of-frame silence (50 ms over TCP, t3.5 = 1.75 ms on a
        // 115200 baud line): RTU has no length field that survives a gap, so the answer breaks
        // into pieces that are no frame; every byte is still counted. The gaps are far longer than
        // the silence so that a busy machine, late to read, still sees each byte alone.
        if (!mbap)
            row(link, serial ? "trickle 60" : "trickle 150", 3000, S::Timeout, 0, 0, 0, 11, 0);
        row(link, "garbage 7", 2000, S::Ok, 0, 0, 0, 7, 0);
        if (mbap)
            row(link, "wrong-tid", 2000, S::Unexpected, 0, 0, 0, 0, 0);
        row(link, "wrong-unit", 2000, S::Unexpected, 0, 0, 0, 0, 0);
        row(link, "wrong-function", 2000, S::Unexpected, 0, 0, 0, 0, 0);
        row(link, "twice", 2000, S::Ok, 0, 1, 0, 0, 0);
        row(link, "delay 1200", 400, S::Timeout, 0, 0, 1, 0, 0);
        if (!mbap)
            row(link, "bad-crc", 2000, S::CrcError, 0, 0, 0, -1, 0);
        row(link, "exception 4", 2000, S::Exception, 4, 0, 0, 0, 0);
        row(link, "short", 2000, S::Malformed, 0, 0, 0, -1, 0);
    }
}

void TestEngineFaults::fault()
{
    QFETCH(QString, link);
    QFETCH(QString, command);
    QFETCH(int, timeoutMs);
    QFETCH(TransactionStatus, status);
    QFETCH(int, exceptionCode);
    QFETCH(int, duplicates);
    QFETCH(int, late);
    QFETCH(int, skippedBytes);
    QFETCH(int, connects);

    if (link == QLatin1String("rtu") && QStandardPaths::findExecutable(QStringLiteral("socat")).isEmpty())
        QSKIP("socat is not installed (Debian: apt-get install socat)");
    QString error;
    Target *t = target(link, &error);
    QVERIFY2(t, qPrintable(error));
    m_current = t;

    // Everything before this row has settled: its records and counters are in.
    QVERIFY(t->probe->waitFor([&] { return t->probe->counters().transactions == quint64(t->probe->records().size()); }, 5000));
    const EngineCounters before = t->probe->counters();

    QVERIFY2(t->server->command("next " + command.toLatin1(), "OK next"), qPrintable(t->server->error()));
    QByteArray sent;
    const std::optional<Transaction> tr = exchange(t, timeoutMs, &sent);
    QVERIFY2(tr, "the engine recorded nothing");
    QVERIFY2(tr->status == status, qPrintable(describe(tr)));
    QCOMPARE(int(tr->exceptionCode), exceptionCode);
    QCOMPARE(tr->request, sent);
    if (status != S::Ok)
        QVERIFY2(!tr->problem.isEmpty(), "a failed transaction must say what was wrong");
    if (status == S::Ok)
        QCOMPARE(responsePdu(*tr, t->url.framing()), expectedReadRegisters(0x03, 0x10, 3));
    if (command.startsWith(QLatin1String("trickle")) && status == S::Ok) {
        // The server sleeps between bytes, so the answer's first and last byte are apart by at
        // least (length - 1) sleeps; a link that stamped the whole answer at once would fail.
        const qint64 gapNs = qint64(command.section(QLatin1Char(' '), 1).toInt()) * 1000000;
        QVERIFY2(tr->doneNs - tr->firstByteNs >= qint64(tr->response.size() - 1) * gapNs,
                 qPrintable(QStringLiteral("first to last byte %1 ns for %2 bytes").arg(tr->doneNs - tr->firstByteNs).arg(tr->response.size())));
    }

    // The server has finished misbehaving (a trickle or a delay may still be under way).
    QVERIFY2(waitServed(t), qPrintable(QStringLiteral("the fault server did not report the request served")));
    if (late > 0) {
        QVERIFY2(t->probe->waitFor([&] { return t->probe->find(tr->id, S::Late).has_value(); }, 5000),
                 qPrintable(QStringLiteral("no late record; counters: ") + describe(t->probe->counters())));
        const Transaction lateRecord = *t->probe->find(tr->id, S::Late);
        QCOMPARE(responsePdu(lateRecord, t->url.framing()), expectedReadRegisters(0x03, 0x10, 3));
        QVERIFY(lateRecord.doneNs - lateRecord.sentNs > qint64(timeoutMs) * 1000000);
    }
    // A second answer or the tail of a slow one may still be on its way to the engine.
    const quint64 inExpected = before.bytesIn + quint64(tr->response.size()); // at least
    QVERIFY(t->probe->waitFor([&] { return t->probe->counters().bytesIn >= inExpected; }, 5000));
    QTest::qWait(status == S::Timeout ? 200 : 100);
    QVERIFY(t->probe->waitFor([&] { return t->probe->counters().transactions == quint64(t->probe->records().size()); }, 5000));
    const EngineCounters after = t->probe->counters();
    const QString counters = describe(after - before);
    QVERIFY2(after.duplicateFrames - before.duplicateFrames == quint64(duplicates), qPrintable(counters));
    QVERIFY2(after.late - before.late == quint64(late), qPrintable(counters));
    if (skippedBytes >= 0)
        QVERIFY2(after.skippedBytes - before.skippedBytes == quint64(skippedBytes), qPrintable(counters));
    // Unsolicited frames: only the second answer of "twice".
    QVERIFY2(after.unsolicitedFrames - before.unsolicitedFrames == quint64(duplicates), qPrintable(counters));

    // And the next transaction is correct again (the link reopened where it had to).
    const std::optional<Transaction> next = exchange(t, 2000);
    QVERIFY2(next && next->isOk(), qPrintable(describe(next) + QStringLiteral("; counters: ") + counters));
    QCOMPARE(responsePdu(*next, t->url.framing()), expectedReadRegisters(0x03, 0x10, 3));
    QVERIFY(waitServed(t));
    QVERIFY(t->probe->waitFor([&] { return t->probe->counters().transactions == quint64(t->probe->records().size()); }, 5000));
    QCOMPARE(int(t->probe->counters().connects - before.connects), connects);
}

QTEST_GUILESS_MAIN(TestEngineFaults)
#include "tst_engine_faults.moc"
