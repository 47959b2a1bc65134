// WatchReader and WatchWriter, through the session document (version 2): good definitions read
// as meant and written back the same; bad ones refused with the path of the value at fault and
// what was expected (more in tests/data/sessions/broken/bad-watches); version 1 documents still
// read, and saving over one says it was upgraded.
#include "session/sessionreader.h"
#include "session/sessionwriter.h"

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

QByteArray document(const QByteArray &watches)
{
    return R"({"format": "mbscope-session", "version": 2, )" + watches + "}";
}

QByteArray goodDocument()
{
    // Every feature of a watch, its links and its log (also validated by tst_sessionschema).
    QFile f(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/watches.mbscope.json"));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestWatchReader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void goodDefinitions();
    void roundTrip();
    void badDefinitions_data();
    void badDefinitions();
    void versionOneUpgraded();
};

void TestWatchReader::goodDefinitions()
{
    const SessionLoadResult r = SessionReader::parse(goodDocument(), QStringLiteral("good.json"));
    QVERIFY2(r.ok(), qPrintable(r.errorText()));
    const SessionWatches &w = r.document->watches;
    QCOMPARE(w.watches.size(), 3);
    const WatchDefinition &g = w.watches.at(0);
    QCOMPARE(g.address, quint16(0x79));
    QCOMPARE(g.quantity, quint16(14));
    QCOMPARE(g.intervalMs, 250);
    QCOMPARE(g.points.size(), 3);
    QCOMPARE(g.points.at(1).format.name(), QStringLiteral("f32-cdab"));
    QCOMPARE(g.points.at(1).scale, 0.5);
    QCOMPARE(g.points.at(2).bitFields.at(1).firstBit, 8);
    QCOMPARE(g.points.at(2).bitFields.at(1).bitCount, 4);
    QCOMPARE(g.points.at(2).bitFields.at(1).states, (QStringList{u"off"_qs, u"on"_qs}));
    QVERIFY(g.points.at(2).writable);
    QCOMPARE(g.rules.at(0).condition, WatchRule::Condition::Outside);
    QCOMPARE(g.rules.at(0).low, 1000.0);
    QCOMPARE(g.rules.at(0).high, 1100.0);
    QCOMPARE(g.rules.at(0).severity, WatchSeverity::Alarm);
    QCOMPARE(g.rules.at(1).condition, WatchRule::Condition::Bits);
    QCOMPARE(g.rules.at(1).low, 8.0);
    QCOMPARE(g.rules.at(2).point, QStringLiteral("134"));
    QCOMPARE(w.watches.at(1).function, quint8(0x18));
    QCOMPARE(w.watches.at(1).quantity, quint16(31));
    QVERIFY(!w.watches.at(1).enabled);
    QVERIFY(w.watches.at(2).enron32);
    QCOMPARE(w.links.size(), 1);
    QCOMPARE(w.links.first().gapMs, 20);
    QCOMPARE(w.links.first().reconnectMaxMs, 5000);
    QVERIFY(w.log);
    QCOMPARE(w.log->mode, WatchLogSettings::Mode::OnChange);
    QCOMPARE(w.log->rollSeconds, 3600);
    QVERIFY(w.log->enabled);
}

void TestWatchReader::roundTrip()
{
    const SessionLoadResult r = SessionReader::parse(goodDocument(), QStringLiteral("good.json"));
    QVERIFY(r.ok());
    const QByteArray written = SessionWriter::toBytes(*r.document);
    const SessionLoadResult again = SessionReader::parse(written, QStringLiteral("written.json"));
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QCOMPARE(again.document->watches, r.document->watches);
    QCOMPARE(SessionWriter::toBytes(*again.document), written);
    QVERIFY(written.contains("\"address\": \"0x0079\""));
    QVERIFY(written.contains("\"bits\": \"8-11\""));
}

void TestWatchReader::badDefinitions_data()
{
    QTest::addColumn<QByteArray>("watches");
    QTest::addColumn<QString>("problem");
    const QByteArray head = R"("watches": [{"name": "a", "target": "tcp://127.0.0.1:502", "address": 0, "quantity": 4, )";
    QTest::newRow("forPolls 0") << head + R"("rules": [{"point": "1", "above": 1, "forPolls": 0}]}])"
                                << u"watches[0].rules[0].forPolls: 0 is below 1"_qs;
    QTest::newRow("no condition") << head + R"("rules": [{"point": "1"}]}])"
                                  << u"watches[0].rules[0]: no condition: give one of above, below, outside, inside, equal, notEqual, bits"_qs;
    QTest::newRow("inside not a pair") << head + R"("rules": [{"point": "1", "inside": [1]}]}])"
                                       << u"watches[0].rules[0].inside: expected [low, high], two numbers, found an array"_qs;
    QTest::newRow("point format") << head + R"("points": [{"address": 0, "format": "f33"}]}])"
                                  << u"watches[0].points[0].format: 'f33' is not a register format"_qs;
    QTest::newRow("f32 past the end") << head + R"("points": [{"address": 3, "format": "f32"}]}])"
                                      << u"watches[0].points[0].format: f32-abcd at 0x0003 takes 2 registers, past the watch's last address 0x0003"_qs;
    QTest::newRow("bit beyond 16") << head + R"("points": [{"address": 0, "bitFields": [{"name": "x", "bits": 16}]}]}])"
                                   << u"watches[0].points[0].bitFields[0].bits: bit 16 is beyond the value's 16 bits (0 to 15)"_qs;
    QTest::newRow("too many states") << head + R"("points": [{"address": 0, "bitFields": [{"name": "x", "bits": 0, "states": ["a", "b", "c"]}]}]}])"
                                     << u"watches[0].points[0].bitFields[0].states: 3 names for a field of 1 bits (at most 2 values)"_qs;
    QTest::newRow("format of a coil") << QByteArray(R"("watches": [{"name": "c", "target": "tcp://127.0.0.1:502", "function": 1, "address": 0, "quantity": 8, "points": [{"address": 0, "format": "u16"}]}])")
                                      << u"watches[0].points[0].format: a watch of coils or discrete inputs (function 1) reads bits: a point has no format"_qs;
    QTest::newRow("enron on coils") << QByteArray(R"("watches": [{"name": "c", "target": "tcp://127.0.0.1:502", "function": 1, "address": 0, "quantity": 8, "enron32": true}])")
                                    << u"watches[0].enron32: 32-bit (Enron) registers are holding or input registers (function 3 or 4), not function 1"_qs;
    QTest::newRow("quantity missing") << QByteArray(R"("watches": [{"name": "c", "target": "tcp://127.0.0.1:502", "address": 0}])")
                                      << u"watches[0]: 'quantity' is missing"_qs;
    QTest::newRow("past 0xFFFF") << QByteArray(R"("watches": [{"name": "c", "target": "tcp://127.0.0.1:502", "address": "0xFFFF", "quantity": 2}])")
                                 << u"watches[0].quantity: 2 addresses from 0xFFFF run past 0xFFFF"_qs;
    QTest::newRow("reconnect max below min") << head + R"("intervalMs": 10}], "watchLinks": [{"target": "tcp://127.0.0.1:502", "reconnectMinMs": 1000, "reconnectMaxMs": 10}])"
                                             << u"watchLinks[0].reconnectMaxMs: 10 is below reconnectMinMs 1000"_qs;
    QTest::newRow("log without directory") << head + R"("intervalMs": 10}], "watchLog": {"mode": "poll"})"
                                           << u"watchLog: 'directory' is missing"_qs;
}

void TestWatchReader::badDefinitions()
{
    QFETCH(QByteArray, watches);
    QFETCH(QString, problem);
    const SessionLoadResult r = SessionReader::parse(document(watches), QStringLiteral("bad.json"));
    QVERIFY(!r.ok());
    QVERIFY2(r.errorText().contains(QStringLiteral("bad.json: ") + problem), qPrintable(r.errorText()));
}

void TestWatchReader::versionOneUpgraded()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("old.mbscope.json"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "mbscope-session", "version": 1, "name": "before watches", "target": {"url": "tcp://127.0.0.1:502"}})");
    }
    const SessionLoadResult r = SessionReader::load(path);
    QVERIFY2(r.ok(), qPrintable(r.errorText()));
    QCOMPARE(r.version, 1);
    QVERIFY(r.document->watches.isEmpty());
    QString error;
    QString notice;
    QVERIFY(SessionWriter::save(*r.document, path, &error, &notice));
    QCOMPARE(notice, path + QStringLiteral(": upgraded from session version 1 to 2 (watches); mbscope versions that read only "
                                           "version 1 no longer open it"));
    const SessionLoadResult saved = SessionReader::load(path);
    QCOMPARE(saved.version, 2);
    QVERIFY(SessionWriter::save(*saved.document, path, &error, &notice));
    QVERIFY(notice.isEmpty()); // already version 2
}

QTEST_GUILESS_MAIN(TestWatchReader)
#include "tst_watchreader.moc"
