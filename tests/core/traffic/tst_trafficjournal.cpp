#include "trafficframes.h"

#include "traffic/trafficjournal.h"

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <csignal>
#include <random>

#include <sys/resource.h>

using namespace mbscope;
using namespace mbscope::testing;

// The journal's format and its reader: round trip, batching, a journal cut at every byte or
// damaged, a write error. The SIGKILLed writer is in tst_trafficlog.
class TestTrafficJournal : public QObject
{
    Q_OBJECT
private slots:
    void crc32();
    void journalRoundTrip();
    void batchByTime();
    void existingJournalKept();
    void truncatedAnywhere();
    void corruptBatch();
    void writeErrorCounted();
};

void TestTrafficJournal::crc32()
{
    // CRC-32/ISO-HDLC check value (the CRC catalogue).
    QCOMPARE(TrafficJournalWriter::crc32("123456789", 9), 0xCBF43926u);
    QCOMPARE(TrafficJournalWriter::crc32("", 0), 0u);
    // The 8-bytes-at-a-time path against a bit-by-bit reference, for every length and alignment.
    std::mt19937 random(7);
    QByteArray data(300, Qt::Uninitialized);
    for (char &c : data)
        c = char(random());
    const auto reference = [](const char *p, int n) {
        quint32 c = 0xFFFFFFFFu;
        for (int i = 0; i < n; ++i) {
            c ^= quint8(p[i]);
            for (int bit = 0; bit < 8; ++bit)
                c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
        }
        return c ^ 0xFFFFFFFFu;
    };
    for (int start = 0; start < 8; ++start)
        for (int n = 0; n < 200; ++n)
            QCOMPARE(TrafficJournalWriter::crc32(data.constData() + start, std::size_t(n)), reference(data.constData() + start, n));
}

void TestTrafficJournal::journalRoundTrip()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("round.mbtl"));
    TrafficJournalWriter::Options options;
    options.batchEntries = 100;
    const qint64 before = QDateTime::currentMSecsSinceEpoch();
    {
        TrafficLog log;
        const quint16 early = log.addLink(QStringLiteral("tcp://10.0.0.1:502")); // named before the journal
        QVERIFY(log.openJournal(path, options));
        for (quint64 i = 0; i < 1050; ++i) {
            const quint16 link = i < 500 ? early : log.addLink(QStringLiteral("rtu-tcp://192.168.127.254:4001"));
            appendMade(log, link, i);
        }
        QCOMPARE(log.journal().batchesWritten(), quint64(10));
        QCOMPARE(log.journal().framesPending(), quint64(50));
    } // closing writes the last 50
    QList<TrafficFrame> frames;
    const TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(r.frames, quint64(1050));
    QCOMPARE(r.batches, quint64(11));
    QCOMPARE(r.goodBytes, r.fileBytes);
    QCOMPARE(r.links, (QStringList{QStringLiteral("tcp://10.0.0.1:502"), QStringLiteral("rtu-tcp://192.168.127.254:4001")}));
    QVERIFY(r.wallClockMs >= before && r.wallClockMs <= QDateTime::currentMSecsSinceEpoch());
    QVERIFY(r.monotonicNs > 0);
    QCOMPARE(r.message, QStringLiteral("recovered 1,050 frames in 11 batches; the journal ends cleanly at byte %1").arg(grouped(r.fileBytes)));
    QCOMPARE(frames.size(), 1050);
    for (int i = 0; i < frames.size(); ++i) {
        const TrafficFrame &f = frames.at(i);
        const TrafficEntry e{f.sequence, f.tNs, f.transactionId, f.link, f.direction, f.verdict, f.bytes};
        QVERIFY2(matches(e, quint64(i)), qPrintable(QString::number(i)));
        QCOMPARE(f.link, quint16(i < 500 ? 0 : 1));
    }
    // 40-byte header, 32 per batch, 28 per record plus the bytes.
    qint64 expected = 40 + 11 * 32 + 2 * 28 + qint64(QByteArray("tcp://10.0.0.1:502").size())
        + qint64(QByteArray("rtu-tcp://192.168.127.254:4001").size());
    for (int i = 0; i < 1050; ++i)
        expected += 28 + i % 37;
    expected += 32 + 28; // the end record's batch, written by close()
    QCOMPARE(r.fileBytes, expected);
}

void TestTrafficJournal::batchByTime()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    TrafficJournalWriter::Options options;
    options.batchEntries = 1000;
    options.batchNs = 1000000; // 1 ms
    TrafficLog log;
    QVERIFY(log.openJournal(dir.filePath(QStringLiteral("time.mbtl")), options));
    log.append(5000000, TrafficDirection::Out, 0, TrafficVerdict::Sent, 1, "a");
    log.append(5500000, TrafficDirection::In, 0, TrafficVerdict::Ok, 1, "b");
    QCOMPARE(log.journal().batchesWritten(), quint64(0));
    log.append(6000000, TrafficDirection::Out, 0, TrafficVerdict::Sent, 2, "c"); // 1 ms after the first
    QCOMPARE(log.journal().batchesWritten(), quint64(1));
    QCOMPARE(log.journal().framesWritten(), quint64(3));
    log.append(7000000, TrafficDirection::In, 0, TrafficVerdict::Ok, 2, "d");
    log.flushIfDue(7999999);
    QCOMPARE(log.journal().batchesWritten(), quint64(1));
    log.flushIfDue(8000000);
    QCOMPARE(log.journal().batchesWritten(), quint64(2));
    log.flushIfDue(9000000); // nothing pending: no empty batch
    QCOMPARE(log.journal().batchesWritten(), quint64(2));
}

void TestTrafficJournal::existingJournalKept()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("kept.mbtl"));
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path));
        appendMade(log, 0, 0);
    }
    const qint64 size = QFileInfo(path).size();
    TrafficLog again;
    QString error;
    QVERIFY(!again.openJournal(path, {}, false, &error));
    QVERIFY2(error.contains(path) && error.contains(QStringLiteral("exists")), qPrintable(error));
    QCOMPARE(QFileInfo(path).size(), size);
    QVERIFY(again.openJournal(path, {}, true, &error));
    again.closeJournal();
    QCOMPARE(QFileInfo(path).size(), 40 + 32 + 28); // the header, then the end record's batch
}

// A journal cut at any byte (the crash that lands inside a write) gives back exactly the batches
// before the cut, and says where it was cut.
void TestTrafficJournal::truncatedAnywhere()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("whole.mbtl"));
    TrafficJournalWriter::Options options;
    options.batchEntries = 5;
    std::vector<qint64> batchEnds;
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path, options));
        batchEnds.push_back(log.journal().bytesWritten());
        for (quint64 i = 0; i < 15; ++i) {
            appendMade(log, 0, i);
            if (log.journal().bytesWritten() != batchEnds.back())
                batchEnds.push_back(log.journal().bytesWritten());
        }
    }
    QCOMPARE(batchEnds.size(), std::size_t(4)); // header, then 3 batches
    QFile whole(path);
    QVERIFY(whole.open(QIODevice::ReadOnly));
    const QByteArray bytes = whole.readAll();
    // Closing wrote the end record's batch after them (not a batch of traffic: not counted).
    const qint64 lastTraffic = batchEnds.back();
    QCOMPARE(qint64(bytes.size()), lastTraffic + 32 + 28);

    const QString cutPath = dir.filePath(QStringLiteral("cut.mbtl"));
    for (qint64 cut = 0; cut <= bytes.size(); ++cut) {
        QFile out(cutPath);
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(bytes.left(cut));
        out.close();
        QList<TrafficFrame> frames;
        const TrafficJournalRecovery r = TrafficJournalReader::readAll(cutPath, &frames);
        const QString where = QStringLiteral("cut at %1: %2").arg(cut).arg(r.message);
        if (cut < 40) {
            QVERIFY2(r.ending == TrafficJournalRecovery::Ending::NotAJournal, qPrintable(where));
            QCOMPARE(frames.size(), 0);
            continue;
        }
        const auto complete = quint64(std::count_if(batchEnds.begin() + 1, batchEnds.end(), [cut](qint64 e) { return e <= cut; }));
        QCOMPARE(r.batches, complete);
        QCOMPARE(r.frames, complete * 5);
        QCOMPARE(quint64(frames.size()), complete * 5);
        for (int i = 0; i < frames.size(); ++i)
            QCOMPARE(frames.at(i).bytes, made(quint64(i)).bytes);
        QCOMPARE(r.goodBytes, cut == bytes.size() ? qint64(bytes.size()) : batchEnds[complete]);
        const QString recovered = QStringLiteral("recovered %1 frames in %2 batches; ").arg(complete * 5).arg(complete);
        if (cut == bytes.size()) {
            QVERIFY2(r.isClean(), qPrintable(where));
            QVERIFY(r.closed);
        } else if (cut == batchEnds[complete]) {
            // What a kill between two batches leaves: whole batches, no end record.
            QCOMPARE(r.ending, TrafficJournalRecovery::Ending::NotClosed);
            QVERIFY(!r.closed);
            QCOMPARE(r.message, recovered + QStringLiteral("truncated: its writer never closed it (killed, crashed or still "
                                                           "writing), it stops after the last complete batch, at byte %1; "
                                                           "whatever the writer held then is not in it")
                                                .arg(grouped(cut)));
        } else if (cut > lastTraffic) {
            QVERIFY2(r.ending == TrafficJournalRecovery::Ending::CutShort, qPrintable(where)); // inside the end record's batch
        } else {
            QVERIFY2(r.ending == TrafficJournalRecovery::Ending::CutShort, qPrintable(where));
            QCOMPARE(r.message, recovered + QStringLiteral("the last batch was cut short at byte %1 and is dropped (it began at byte %2)")
                                                .arg(grouped(cut), grouped(batchEnds[complete])));
        }
    }
}

void TestTrafficJournal::corruptBatch()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.mbtl"));
    TrafficJournalWriter::Options options;
    options.batchEntries = 4;
    qint64 secondBatch = 0;
    {
        TrafficLog log;
        QVERIFY(log.openJournal(path, options));
        for (quint64 i = 0; i < 12; ++i) {
            appendMade(log, 0, i, 10);
            if (i == 3)
                secondBatch = log.journal().bytesWritten();
        }
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray good = file.readAll();
    file.close();
    const auto check = [&](qint64 offset, const QString &expected) {
        QByteArray bad = good;
        bad[offset] = char(bad[offset] ^ 0x01);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(bad);
        file.close();
        QList<TrafficFrame> frames;
        const TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
        QCOMPARE(r.ending, TrafficJournalRecovery::Ending::Corrupt);
        QCOMPARE(r.frames, quint64(4));
        QCOMPARE(frames.size(), 4);
        QCOMPARE(r.goodBytes, secondBatch);
        QVERIFY2(r.message.contains(expected), qPrintable(r.message));
        QVERIFY2(r.message.startsWith(QStringLiteral("recovered 4 frames in 1 batches; the batch at byte %1 is damaged")
                                          .arg(grouped(secondBatch))),
                 qPrintable(r.message));
    };
    check(secondBatch + 32 + 28 + 3, QStringLiteral("payload CRC")); // a frame byte
    check(secondBatch + 4, QStringLiteral("header is damaged"));     // the payload size

    QByteArray notJournal = good;
    notJournal[0] = 'X';
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(notJournal);
    file.close();
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, {});
    QCOMPARE(r.ending, TrafficJournalRecovery::Ending::NotAJournal);
    QVERIFY2(r.message.contains(QStringLiteral("not an mbscope traffic journal")), qPrintable(r.message));
    const TrafficJournalRecovery missing = TrafficJournalReader::read(dir.filePath(QStringLiteral("none.mbtl")), {});
    QCOMPARE(missing.ending, TrafficJournalRecovery::Ending::Unreadable);
    QVERIFY2(missing.message.contains(QStringLiteral("none.mbtl")), qPrintable(missing.message));
}

// A full disk (here a file size limit, EFBIG) stops the journal with a message and counts every
// frame it could not write; the log in memory and the batches already written stay whole.
void TestTrafficJournal::writeErrorCounted()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("full.mbtl"));
    rlimit saved{};
    QCOMPARE(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    auto *previous = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved;
    small.rlim_cur = 4096;
    QCOMPARE(::setrlimit(RLIMIT_FSIZE, &small), 0);
    TrafficLog log;
    TrafficJournalWriter::Options options;
    options.batchEntries = 10;
    const bool opened = log.openJournal(path, options);
    for (quint64 i = 0; opened && i < 1000; ++i)
        appendMade(log, 0, i, 20);
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    QVERIFY(opened);
    QVERIFY2(log.journal().error().contains(QStringLiteral("write failed after")), qPrintable(log.journal().error()));
    QCOMPARE(log.journal().framesWritten() + log.journal().framesLost() + log.journal().framesPending(), quint64(1000));
    QVERIFY(log.journal().framesLost() > 0);
    QCOMPARE(log.size(), quint64(1000));
    log.closeJournal();
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, {});
    QCOMPARE(r.frames, log.journal().framesWritten());
    // The end record could not be written either.
    QVERIFY2(r.ending == TrafficJournalRecovery::Ending::NotClosed || r.ending == TrafficJournalRecovery::Ending::CutShort,
             qPrintable(r.message));
}

QTEST_GUILESS_MAIN(TestTrafficJournal)
#include "tst_trafficjournal.moc"
