#include "trafficframes.h"

#include "traffic/trafficjournal.h"
#include "traffic/trafficmetadata.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QTemporaryDir>
#include <QtCore/QtEndian>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::testing;

// A journal's metadata (record kind 3, format version 2): what was recorded, read back from the
// journal alone; notes (kind 4); version 1 journals still read; TrafficRecording's line.
class TestTrafficMetadata : public QObject
{
    Q_OBJECT
private slots:
    void jsonRoundTrip();
    void jsonProblemsNamed();
    void journalRoundTrip();
    void metadataOnDiskBeforeFirstFrame();
    void notes();
    void versionOneStillRead();
    void newerVersionRefused();
    void recordingSummary();
};

namespace {

TrafficMetadata sample()
{
    TrafficMetadata m = TrafficMetadata::forCommand(QStringLiteral("poll"),
                                                    {QStringLiteral("--target"), QStringLiteral("tcp://127.0.0.1:1502")},
                                                    QStringLiteral("9.8.7"));
    m.started = QDateTime::fromMSecsSinceEpoch(m.started.toMSecsSinceEpoch(), Qt::UTC); // ms, as written
    m.target = QStringLiteral("tcp://127.0.0.1:1502");
    m.profileName = QStringLiteral("rosrao-gamma");
    m.profileSource = QStringLiteral("shipped");
    m.requests = {TrafficMetadataRequest{QStringLiteral("Read Holding Registers 0 x10"),
                                         QStringLiteral("Read Holding Registers, unit 1, 10 registers at 0 (0x0000), 40001-40010"),
                                         QByteArray::fromHex("00010000000601030000000A")}};
    m.settings.insert(QStringLiteral("interval_ms"), 100);
    return m;
}

// Rewrites a journal's version field and its header CRC.
void setVersion(const QString &path, quint32 version)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadWrite));
    QByteArray header = file.read(40);
    qToLittleEndian<quint32>(version, header.data() + 8);
    qToLittleEndian<quint32>(TrafficJournalWriter::crc32(header.constData(), 36), header.data() + 36);
    QVERIFY(file.seek(0));
    QCOMPARE(file.write(header), qint64(40));
}

} // namespace

void TestTrafficMetadata::jsonRoundTrip()
{
    TrafficMetadata m = sample();
    TrafficMetadata back;
    QString error;
    QVERIFY2(TrafficMetadata::fromJson(m.toUtf8(), &back, &error), qPrintable(error));
    QCOMPARE(back, m);
    QVERIFY(!back.host.isEmpty());
    QCOMPARE(back.arguments, (QStringList{QStringLiteral("--target"), QStringLiteral("tcp://127.0.0.1:1502")}));

    TrafficMetadata server;
    server.role = TrafficMetadata::Role::Server;
    server.listen = {QStringLiteral("rtu-tcp://127.0.0.1:4001"), QStringLiteral("udp://127.0.0.1:1502")};
    QVERIFY2(TrafficMetadata::fromJson(server.toUtf8(), &back, &error), qPrintable(error));
    QCOMPARE(back, server);

    const QStringList lines = m.summaryLines();
    QVERIFY2(lines.value(0).startsWith(QStringLiteral("recorded      poll by mbscope 9.8.7 on ")), qPrintable(lines.join(QLatin1Char('\n'))));
    QVERIFY(lines.contains(QStringLiteral("target        tcp://127.0.0.1:1502")));
    QVERIFY(lines.contains(QStringLiteral("profile       rosrao-gamma (shipped)")));
}

void TestTrafficMetadata::jsonProblemsNamed()
{
    TrafficMetadata m;
    QString error;
    QVERIFY(!TrafficMetadata::fromJson("[1]", &m, &error));
    QCOMPARE(error, QStringLiteral("metadata is not a JSON object"));
    QVERIFY(!TrafficMetadata::fromJson(R"({"target": 5})", &m, &error));
    QCOMPARE(error, QStringLiteral("metadata \"target\": expected a string"));
    QVERIFY(!TrafficMetadata::fromJson(R"({"role": "observer"})", &m, &error));
    QCOMPARE(error, QStringLiteral("metadata \"role\": 'observer', expected client or server"));
    QVERIFY(!TrafficMetadata::fromJson(R"({"requests": [{"hex": 3}]})", &m, &error));
    QCOMPARE(error, QStringLiteral("\"requests\"[0]: metadata \"hex\": expected a string"));
    QVERIFY(!TrafficMetadata::fromJson(R"({"started": "yesterday"})", &m, &error));
    QVERIFY(error.contains(QLatin1String("'yesterday' is not an ISO 8601 time")));
    // Unknown keys are a newer mbscope's: kept out, not refused.
    QVERIFY(TrafficMetadata::fromJson(R"({"command": "poll", "future": {"x": 1}})", &m, &error));
    QCOMPARE(m.command, QStringLiteral("poll"));
}

void TestTrafficMetadata::journalRoundTrip()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("meta.mbscope.journal"));
    const TrafficMetadata m = sample();
    TrafficJournalWriter::Options options;
    options.batchEntries = 10;
    options.metadata = m.toUtf8();
    {
        TrafficLog log;
        // Frames logged before the journal opened: the journal's first frame is not number 0,
        // and the metadata batch (no frames) must not make that look like a gap.
        for (quint64 i = 0; i < 5; ++i)
            appendMade(log, 0, i);
        QVERIFY(log.openJournal(path, options));
        QCOMPARE(log.journal().batchesWritten(), quint64(1)); // the metadata, at once
        for (quint64 i = 5; i < 40; ++i)
            appendMade(log, log.addLink(QStringLiteral("tcp://127.0.0.1:1502")), i);
    }
    QList<TrafficFrame> frames;
    const TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(r.version, 3u);
    QCOMPARE(r.frames, quint64(35));
    QCOMPARE(r.batches, quint64(5)); // metadata + 10 + 10 + 10 + 5
    QCOMPARE(frames.constFirst().sequence, quint64(5));
    TrafficMetadata back;
    QString error;
    QVERIFY2(TrafficMetadata::fromJson(r.metadata, &back, &error), qPrintable(error));
    QCOMPARE(back, m);
}

void TestTrafficMetadata::metadataOnDiskBeforeFirstFrame()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("early.mbscope.journal"));
    // One sample: each call stamps its start time (in ms), so a second call compared with the
    // first differed whenever a millisecond passed between them (on a loaded machine).
    const QByteArray metadata = sample().toUtf8();
    TrafficJournalWriter::Options options;
    options.metadata = metadata;
    TrafficLog log;
    QVERIFY(log.openJournal(path, options));
    appendMade(log, 0, 0); // pending, not written: a kill now loses it, never the metadata
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, {});
    // Still being written: whole batches, no end record yet.
    QVERIFY2(r.ending == TrafficJournalRecovery::Ending::NotClosed, qPrintable(r.message));
    QCOMPARE(r.frames, quint64(0));
    QCOMPARE(r.metadata, metadata);
    // An existing journal is evidence: refused, and says so.
    TrafficLog second;
    QString error;
    QVERIFY(!second.openJournal(path, options, false, &error));
    QVERIFY2(error.contains(QLatin1String("the file exists")), qPrintable(error));
}

void TestTrafficMetadata::notes()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("notes.mbscope.journal"));
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path));
        const quint16 link = log.addLink(QStringLiteral("tcp://127.0.0.1:1502"));
        log.append(100, TrafficDirection::In, link, TrafficVerdict::Ok, 1, "req");
        log.annotate(link, 1, 150, R"({"faults":["slow"]})");
        log.append(200, TrafficDirection::Out, link, TrafficVerdict::Ok, 1, "ans");
        QCOMPARE(log.journal().framesPending(), quint64(2)); // a note is not a frame
    }
    QList<QByteArray> seen;
    quint64 frames = 0;
    const TrafficJournalRecovery r = TrafficJournalReader::read(
        path, [&](const TrafficEntry &) { ++frames; },
        [&](const TrafficJournalNote &note) {
            QCOMPARE(note.transactionId, quint64(1));
            QCOMPARE(note.tNs, qint64(150));
            seen.append(note.json.toByteArray());
        });
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(frames, quint64(2));
    QCOMPARE(r.notes, quint64(1));
    QCOMPARE(seen, (QList<QByteArray>{R"({"faults":["slow"]})"}));
}

void TestTrafficMetadata::versionOneStillRead()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("v1.mbtl"));
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path));
        for (quint64 i = 0; i < 20; ++i)
            appendMade(log, 0, i);
    }
    // Version 1 had no end record: the one closing wrote (the last 32 + 28 bytes) goes.
    QVERIFY(QFile::resize(path, QFileInfo(path).size() - 60));
    setVersion(path, 1);
    QList<TrafficFrame> frames;
    TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(r.version, 1u);
    QCOMPARE(frames.size(), 20);
    QVERIFY(r.metadata.isEmpty());

    // A metadata record is version 2's: in a version 1 file it is damage.
    const QString withMetadata = dir.filePath(QStringLiteral("v1meta.mbtl"));
    {
        TrafficJournalWriter::Options options;
        options.metadata = sample().toUtf8();
        TrafficLog log;
        QVERIFY(log.openJournal(withMetadata, options));
    }
    setVersion(withMetadata, 1);
    r = TrafficJournalReader::read(withMetadata, {});
    QCOMPARE(r.ending, TrafficJournalRecovery::Ending::Corrupt);
    QVERIFY(r.metadata.isEmpty());
}

void TestTrafficMetadata::newerVersionRefused()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("v4.mbtl"));
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path));
    }
    setVersion(path, 4);
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, {});
    QCOMPARE(r.ending, TrafficJournalRecovery::Ending::NotAJournal);
    QVERIFY2(r.message.endsWith(QLatin1String("journal version 4 (header 40 bytes) is not one this mbscope reads (versions 1 to 3)")),
             qPrintable(r.message));
}

void TestTrafficMetadata::recordingSummary()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("rec.mbscope.journal"));
    TrafficRecording recording;
    QString error;
    QVERIFY2(recording.open(path, sample(), false, &error), qPrintable(error));
    TrafficLog *log = recording.log();
    QCOMPARE(log->limits().maxEntries, TrafficRecording::kMemoryEntries);
    const quint16 link = log->addLink(QStringLiteral("tcp://127.0.0.1:1502"));
    // Two transactions, the second retried once, and a late answer to the first.
    log->append(10, TrafficDirection::Out, link, TrafficVerdict::Sent, 1, "a");
    log->append(20, TrafficDirection::In, link, TrafficVerdict::Ok, 1, "b");
    log->append(30, TrafficDirection::Out, link, TrafficVerdict::Sent, 2, "c");
    log->append(40, TrafficDirection::Out, link, TrafficVerdict::Sent, 2, "c");
    log->append(50, TrafficDirection::In, link, TrafficVerdict::Late, 1, "b");
    recording.close();
    QCOMPARE(recording.frames(), quint64(5));
    QCOMPARE(recording.transactions(), quint64(2));
    QCOMPARE(recording.summary(), QStringLiteral("recorded 5 frames (2 transactions) to %1").arg(path));

    TrafficRecording again;
    QVERIFY(!again.open(path, sample(), false, &error));
    QVERIFY2(error.startsWith(path + QStringLiteral(": cannot create the traffic journal: the file exists")), qPrintable(error));
    QVERIFY2(again.open(path, sample(), true, &error), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestTrafficMetadata)
#include "tst_trafficmetadata.moc"
