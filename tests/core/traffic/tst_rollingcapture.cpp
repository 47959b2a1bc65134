// The window's always-on recording: journals in a capture folder, named by start and target, in
// parts of a bounded size, the folder under a quota, a marker while a journal is written so that
// a crash leaves it recoverable, and a move (Save) that the writer follows.
#include "traffic/capturedirectory.h"
#include "traffic/rollingcapture.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QSysInfo>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

class TestRollingCapture : public QObject
{
    Q_OBJECT
private slots:
    void namesByStartAndTarget();
    void rotatesIntoParts();
    void quotaDeletesOldestOnly();
    void abandonedJournalsAreFound();
    void moveKeepsWriting();
    void unwritableFolderIsSaid();
};

namespace {

void appendFrames(TrafficLog *log, quint16 link, int count, int size = 8)
{
    const QByteArray bytes(size, '\x11');
    for (int i = 0; i < count; ++i)
        log->append(1'000'000 + i, i % 2 ? TrafficDirection::In : TrafficDirection::Out, link,
                    i % 2 ? TrafficVerdict::Ok : TrafficVerdict::Sent, quint64(i / 2 + 1), bytes);
}

quint64 framesIn(const QString &path, TrafficJournalRecovery *recovery = nullptr)
{
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, {});
    if (recovery)
        *recovery = r;
    return r.frames;
}

void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

} // namespace

void TestRollingCapture::namesByStartAndTarget()
{
    QTemporaryDir dir;
    const CaptureDirectory captures(dir.path());
    const QDateTime start(QDate(2026, 11, 26), QTime(0, 15, 2));
    const QString first = captures.newJournalPath(start, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    QCOMPARE(QFileInfo(first).fileName(), QStringLiteral("20261126-001502-rtu-tcp_127.0.0.1_4001.mbscope.journal"));
    QCOMPARE(QFileInfo(captures.newJournalPath(start, QStringLiteral("rtu:///dev/ttyUSB0?baud=9600&parity=E"), 3)).fileName(),
             QStringLiteral("20261126-001502-rtu_dev_ttyUSB0_baud_9600_parity_E-part3.mbscope.journal"));
    // Never the name of a file that exists.
    writeFile(first, "x");
    QCOMPARE(QFileInfo(captures.newJournalPath(start, QStringLiteral("rtu-tcp://127.0.0.1:4001"))).fileName(),
             QStringLiteral("20261126-001502-rtu-tcp_127.0.0.1_4001-2.mbscope.journal"));
}

void TestRollingCapture::rotatesIntoParts()
{
    QTemporaryDir dir;
    RollingCapture::Policy policy;
    policy.rotateBytes = 64 * 1024;
    QString error;
    {
        RollingCapture capture(CaptureDirectory(dir.path()), policy);
        QVERIFY2(capture.start(QStringLiteral("tcp://127.0.0.1:502"), &error), qPrintable(error));
        TrafficLog *log = capture.log();
        const quint16 link = log->addLink(QStringLiteral("tcp://127.0.0.1:502"));
        // 36 bytes a frame on disk: ~1,800 frames a part, 10,000 frames make several parts.
        appendFrames(log, link, 10'000);
        QVERIFY(log->rotationError().isEmpty());
        QVERIFY(QFile::exists(capture.currentPath() + QStringLiteral(".open")));
    }
    const QList<CaptureDirectory::Journal> parts = CaptureDirectory(dir.path()).journals();
    QVERIFY2(parts.size() >= 4, qPrintable(QString::number(parts.size())));
    quint64 total = 0;
    for (const CaptureDirectory::Journal &part : parts) {
        TrafficJournalRecovery r;
        total += framesIn(part.path, &r);
        QVERIFY2(r.isClean(), qPrintable(r.message));
        // Each part names its links: it can be analysed alone.
        QCOMPARE(r.links, QStringList{QStringLiteral("tcp://127.0.0.1:502")});
        QVERIFY(part.bytes < policy.rotateBytes + 64 * 1024);
        QVERIFY(!QFile::exists(part.path + QStringLiteral(".open")));
    }
    QCOMPARE(total, quint64(10'000));
}

void TestRollingCapture::quotaDeletesOldestOnly()
{
    QTemporaryDir dir;
    const CaptureDirectory captures(dir.path());
    const QDateTime t0 = QDateTime::currentDateTime().addDays(-1);
    QStringList paths;
    for (int i = 0; i < 4; ++i) {
        const QString path = captures.newJournalPath(t0.addSecs(i), QStringLiteral("tcp://h"));
        writeFile(path, QByteArray(1000, 'j'));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.setFileTime(t0.addSecs(i * 60), QFileDevice::FileModificationTime));
        paths.append(path);
    }
    // The newest is kept on request, the second oldest is being written (a live marker).
    QVERIFY(CaptureDirectory::markOpen(paths.at(1)));
    const QStringList deleted = captures.enforceQuota(2500, {paths.at(3)});
    QCOMPARE(deleted, (QStringList{paths.at(0), paths.at(2)}));
    QVERIFY(QFile::exists(paths.at(1)));
    QVERIFY(QFile::exists(paths.at(3)));
}

void TestRollingCapture::abandonedJournalsAreFound()
{
    QTemporaryDir dir;
    RollingCapture::Policy policy;
    QString error;
    RollingCapture live(CaptureDirectory(dir.path()), policy);
    QVERIFY(live.start(QStringLiteral("tcp://live"), &error));
    // A journal whose writer is gone: the marker names a process that has ended.
    QProcess done;
    done.start(QStringLiteral("true"));
    QVERIFY(done.waitForFinished());
    const qint64 deadPid = done.processId() > 0 ? done.processId() : 999'999;
    const QString crashed = CaptureDirectory(dir.path()).newJournalPath(QDateTime::currentDateTime().addSecs(-60), QStringLiteral("tcp://gone"));
    writeFile(crashed, "MBSCTLOG");
    writeFile(crashed + QStringLiteral(".open"), QByteArray::number(deadPid) + '\n' + QSysInfo::machineHostName().toUtf8() + '\n');
    QCOMPARE(CaptureDirectory(dir.path()).abandoned(), QStringList{crashed});
    CaptureDirectory::markClosed(crashed);
    QVERIFY(CaptureDirectory(dir.path()).abandoned().isEmpty());
}

void TestRollingCapture::moveKeepsWriting()
{
    QTemporaryDir dir;
    QTemporaryDir sessionDir;
    RollingCapture::Policy policy;
    QString error;
    RollingCapture capture(CaptureDirectory(dir.path()), policy);
    QVERIFY(capture.start(QStringLiteral("tcp://127.0.0.1:502"), &error));
    const quint16 link = capture.log()->addLink(QStringLiteral("tcp://127.0.0.1:502"));
    appendFrames(capture.log(), link, 100);
    capture.log()->flush();
    const QString target = sessionDir.filePath(QStringLiteral("bench.mbscope.journal"));
    QVERIFY2(capture.moveTo(target, &error), qPrintable(error));
    QCOMPARE(capture.currentPath(), target);
    QVERIFY(CaptureDirectory(dir.path()).journals().isEmpty());
    appendFrames(capture.log(), link, 100);
    // A second move onto a file that exists is refused: a journal is never overwritten.
    QVERIFY(!capture.moveTo(target, &error));
    QVERIFY2(error.contains(QStringLiteral("never overwritten")), qPrintable(error));
    capture.finish();
    QCOMPARE(framesIn(target), quint64(200));
    QVERIFY(!QFile::exists(target + QStringLiteral(".open")));
}

void TestRollingCapture::unwritableFolderIsSaid()
{
    QTemporaryDir dir;
    const QString blocker = dir.filePath(QStringLiteral("file"));
    writeFile(blocker, "not a folder");
    RollingCapture capture(CaptureDirectory(blocker + QStringLiteral("/captures")), RollingCapture::Policy{});
    QString error;
    QVERIFY(!capture.start(QStringLiteral("tcp://h"), &error));
    QVERIFY2(error.contains(QStringLiteral("cannot create the capture folder")), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestRollingCapture)
#include "tst_rollingcapture.moc"
