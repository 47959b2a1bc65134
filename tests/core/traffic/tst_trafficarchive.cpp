// TrafficArchive: frames written to a journal of its own a batch at a time and read back by
// sequence, the partial last batch from memory; visits forward and back across batches; the
// journal leaves no name behind in its folder; a frame out of order is refused; a damaged batch
// is said, not shown as traffic.
#include "traffic/trafficarchive.h"

#include <QtCore/QDir>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// Frame n: its own bytes (n as 4 bytes), time and transaction, in or out by parity.
TrafficFrame numbered(quint64 n)
{
    TrafficFrame f;
    f.sequence = n;
    f.tNs = qint64(n) * 1000 + 7;
    f.transactionId = n / 2 + 1;
    f.link = quint16(n % 3);
    f.direction = n % 2 ? TrafficDirection::In : TrafficDirection::Out;
    f.verdict = n % 2 ? TrafficVerdict::Ok : TrafficVerdict::Sent;
    f.bytes = QByteArray(4, '\0');
    for (int i = 0; i < 4; ++i)
        f.bytes[i] = char((n >> (8 * i)) & 0xFF);
    return f;
}

TrafficEntry entry(const TrafficFrame &f)
{
    return TrafficEntry{f.sequence, f.tNs, f.transactionId, f.link, f.direction, f.verdict, f.bytes};
}

void checkFrame(const TrafficEntry &e, quint64 n)
{
    const TrafficFrame f = numbered(n);
    QCOMPARE(e.sequence, n);
    QCOMPARE(e.tNs, f.tNs);
    QCOMPARE(e.transactionId, f.transactionId);
    QCOMPARE(e.link, f.link);
    QCOMPARE(e.direction, f.direction);
    QCOMPARE(e.verdict, f.verdict);
    QCOMPARE(e.bytes.toByteArray(), f.bytes);
}

} // namespace

class TestTrafficArchive : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void framesComeBackBySequence();
    void visitsCrossBatches();
    void leavesNothingInTheFolder();
    void refusesAFrameOutOfOrder();
    void damagedBatchIsSaid();
};

void TestTrafficArchive::framesComeBackBySequence()
{
    QTemporaryDir dir;
    TrafficArchive archive;
    QString error;
    QVERIFY2(archive.open(dir.path(), &error), qPrintable(error));
    // Five whole batches and part of a sixth (in memory until its batch fills).
    const quint64 count = 5 * TrafficArchive::kBatchFrames + 100;
    for (quint64 n = 0; n < count; ++n)
        QVERIFY(archive.append(entry(numbered(n))));
    QCOMPARE(archive.size(), count);
    QVERIFY(archive.diskBytes() > qint64(5 * TrafficArchive::kBatchFrames * (28 + 4)));
    // Far apart, more batches than the cache holds, then back to the first.
    for (quint64 n : {quint64(0), quint64(1), count - 1, quint64(3000), quint64(1023), quint64(1024), quint64(5119),
                      quint64(5120), quint64(2048), quint64(0)})
        checkFrame(archive.at(n), n);
    const TrafficEntry past = archive.at(count);
    QCOMPARE(past.verdict, TrafficVerdict::Garbage);
    QVERIFY(past.bytes.isEmpty());
    QVERIFY(archive.error().isEmpty());
    // Memory: the index, the partial batch and at most kCachedBatches decoded ones.
    QVERIFY(archive.memoryBytes() < std::size_t(TrafficArchive::kCachedBatches + 2) * TrafficArchive::kBatchFrames * 80);
}

void TestTrafficArchive::visitsCrossBatches()
{
    QTemporaryDir dir;
    TrafficArchive archive;
    QVERIFY(archive.open(dir.path()));
    const quint64 count = 3 * TrafficArchive::kBatchFrames + 10;
    for (quint64 n = 0; n < count; ++n)
        QVERIFY(archive.append(entry(numbered(n))));
    quint64 next = 1000;
    archive.visit(1000, true, [&](const TrafficEntry &e) {
        if (e.sequence != next)
            return false;
        ++next;
        return true;
    });
    QCOMPARE(next, count);
    quint64 expected = count - 1;
    quint64 seen = 0;
    archive.visit(count - 1, false, [&](const TrafficEntry &e) {
        if (e.sequence != expected || e.bytes.toByteArray() != numbered(expected).bytes)
            return false;
        ++seen;
        if (expected == 0)
            return true;
        --expected;
        return true;
    });
    QCOMPARE(seen, count);
    // Stopping early stops.
    int visited = 0;
    archive.visit(0, true, [&](const TrafficEntry &) { return ++visited < 5; });
    QCOMPARE(visited, 5);
}

void TestTrafficArchive::leavesNothingInTheFolder()
{
    QTemporaryDir dir;
    {
        TrafficArchive archive;
        QVERIFY(archive.open(dir.path() + QStringLiteral("/made")));
        for (quint64 n = 0; n < 3000; ++n)
            QVERIFY(archive.append(entry(numbered(n))));
        checkFrame(archive.at(5), 5);
        // Unlinked while open: a kill leaves nothing behind either.
        QVERIFY(QDir(dir.path() + QStringLiteral("/made")).entryList(QDir::Files).isEmpty());
        archive.clear();
        QCOMPARE(archive.size(), quint64(0));
        QVERIFY(!archive.isOpen());
    }
    QVERIFY(QDir(dir.path() + QStringLiteral("/made")).entryList(QDir::Files).isEmpty());
}

void TestTrafficArchive::refusesAFrameOutOfOrder()
{
    QTemporaryDir dir;
    TrafficArchive archive;
    QVERIFY(!archive.append(entry(numbered(0)))); // not open
    QVERIFY(archive.open(dir.path()));
    QVERIFY(archive.append(entry(numbered(0))));
    QVERIFY(!archive.append(entry(numbered(2))));
    QCOMPARE(archive.size(), quint64(1));
    // A folder that cannot be made is said.
    QFile file(dir.filePath(QStringLiteral("plain")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.close();
    TrafficArchive other;
    QString error;
    QVERIFY(!other.open(dir.filePath(QStringLiteral("plain/sub")), &error));
    QVERIFY2(error.contains(QStringLiteral("plain/sub")), qPrintable(error));
}

// The journal's batches are checked by their CRCs when read back: a byte changed on disk
// gives an entry marked Garbage with no bytes and an error, never other traffic.
void TestTrafficArchive::damagedBatchIsSaid()
{
    QTemporaryDir dir;
    TrafficArchive archive;
    QVERIFY(archive.open(dir.path()));
    for (quint64 n = 0; n < quint64(2 * TrafficArchive::kBatchFrames); ++n)
        QVERIFY(archive.append(entry(numbered(n))));
    // The file is unlinked: reach it through the process's descriptors.
    QString victim;
    for (const QFileInfo &fd : QDir(QStringLiteral("/proc/self/fd")).entryInfoList(QDir::System | QDir::Files)) {
        if (fd.symLinkTarget().contains(QStringLiteral("traffic-list-")))
            victim = fd.absoluteFilePath();
    }
    if (victim.isEmpty())
        QSKIP("no /proc/self/fd to reach the unlinked journal through");
    QFile file(victim);
    QVERIFY(file.open(QIODevice::ReadWrite));
    // Inside the second batch's payload: 40-byte header, first batch 32 + 1024 * (28 + 4) bytes.
    const qint64 at = 40 + 32 + 1024 * 32 + 32 + 28 + 1;
    QVERIFY(file.seek(at));
    char c = 0;
    QVERIFY(file.getChar(&c));
    QVERIFY(file.seek(at));
    QVERIFY(file.putChar(char(c ^ 0x5A)));
    file.close();
    checkFrame(archive.at(5), 5);
    const TrafficEntry damaged = archive.at(TrafficArchive::kBatchFrames + 3);
    QCOMPARE(damaged.verdict, TrafficVerdict::Garbage);
    QVERIFY(damaged.bytes.isEmpty());
    QVERIFY2(archive.error().contains(QStringLiteral("damaged")), qPrintable(archive.error()));
}

QTEST_GUILESS_MAIN(TestTrafficArchive)
#include "tst_trafficarchive.moc"
