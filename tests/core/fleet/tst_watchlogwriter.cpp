// WatchLogWriter and its WatchLogQueue: what waits for the disk is bounded. The writer's thread is
// held (as a disk that does not take the rows would hold it: a write that blocks) while the
// samples of thousands of polls are offered: the queue stays within its bytes, the rows that do
// not fit are counted by watch, and once the thread is free the log says it fell behind once,
// writes every row it kept, notes the gap in the events file and reports the rows dropped.
// Before the queue, the fleet's samples waited in the thread's event queue, with no bound
// (802 MiB after 720,000 polls of 20 watches x 125 registers, bench_workspace --csv --soak-polls).
#include "fleet/watchlogwriter.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QSemaphore>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

SessionWatches twoWatches(const QString &directory)
{
    SessionWatches s;
    for (const char *name : {"fast", "slow"}) {
        WatchDefinition w;
        w.name = QLatin1String(name);
        w.target = QStringLiteral("tcp://127.0.0.1:5020");
        w.address = 0;
        w.quantity = 10;
        s.watches.append(w);
    }
    WatchLogSettings log;
    log.enabled = true;
    log.directory = directory;
    s.log = log;
    return s;
}

QList<WatchSample> batch(int watch, quint64 firstPoll, int count)
{
    QList<WatchSample> samples;
    for (int i = 0; i < count; ++i) {
        WatchSample s;
        s.watch = watch;
        s.watchName = watch == 0 ? QStringLiteral("fast") : QStringLiteral("slow");
        s.status = WatchSample::Status::Ok;
        s.timeMs = 1'795'000'000'000 + qint64(firstPoll + quint64(i));
        s.poll = firstPoll + quint64(i);
        for (int a = 0; a < 10; ++a) {
            WatchPointValue v;
            v.address = quint16(a);
            v.value = a;
            v.text = QString::number(1000 + a);
            s.values.append(v);
        }
        samples.append(s);
    }
    return samples;
}

QStringList lines(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

} // namespace

class TestWatchLogWriter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void queueKeepsWithinItsBytes();
    void heldWriterDropsAndSaysSoOnce();
    void nothingQueuedWhileLoggingIsOff();
};

void TestWatchLogWriter::queueKeepsWithinItsBytes()
{
    const qint64 row = WatchLogQueue::rowBytes(batch(0, 1, 1).first());
    QVERIFY(row > 10 * qint64(sizeof(WatchPointValue)));
    WatchLogQueue queue(row * 100);
    QVERIFY(queue.pushStarted({}));
    QVERIFY(!queue.pushSamples(batch(0, 1, 60)));
    QVERIFY(!queue.pushSamples(batch(1, 1, 60))); // 40 fit, 20 dropped
    QVERIFY(!queue.pushSamples(batch(0, 61, 5)));  // none fit
    QCOMPARE(queue.bytes(), row * 100);
    QVERIFY(!queue.pushStopped()); // always fits
    const QMap<int, quint64> dropped = queue.takeDropped();
    QCOMPARE(dropped.value(0), quint64(5));
    QCOMPARE(dropped.value(1), quint64(20));
    QVERIFY(queue.takeDropped().isEmpty());
    QCOMPARE(queue.take()->kind, WatchLogQueue::Entry::Kind::Started);
    QCOMPARE(queue.take()->samples.size(), 60);
    const std::optional<WatchLogQueue::Entry> second = queue.take();
    QCOMPARE(second->samples.size(), 40);
    QCOMPARE(second->samples.last().poll, quint64(40));
    QCOMPARE(queue.bytes(), 0);
    QCOMPARE(queue.take()->kind, WatchLogQueue::Entry::Kind::Stopped);
    QVERIFY(!queue.take());
    QVERIFY(queue.pushSamples(batch(0, 66, 1))); // empty again: the taker is woken
}

void TestWatchLogWriter::heldWriterDropsAndSaysSoOnce()
{
    QTemporaryDir dir;
    const SessionWatches watches = twoWatches(dir.path());
    const qint64 row = WatchLogQueue::rowBytes(batch(0, 1, 1).first());
    QThread thread;
    auto *writer = new WatchLogWriter(row * 500);
    writer->moveToThread(&thread);
    connect(&thread, &QThread::finished, writer, &QObject::deleteLater);
    QSignalSpy dropping(writer, &WatchLogWriter::dropping);
    QSignalSpy caughtUp(writer, &WatchLogWriter::caughtUp);
    QSignalSpy droppedRows(writer, &WatchLogWriter::droppedRows);
    QSignalSpy closed(writer, &WatchLogWriter::closed);
    QSignalSpy drained(writer, &WatchLogWriter::drained);
    thread.start();
    QMetaObject::invokeMethod(writer, [writer, &watches] { writer->configure(watches.log, QString()); }, Qt::BlockingQueuedConnection);
    writer->offerStarted(watches);

    // The writer's thread is held, as a write the disk does not take would hold it.
    QSemaphore held;
    QSemaphore release;
    QMetaObject::invokeMethod(writer, [&] {
        held.release();
        release.acquire();
    });
    QVERIFY(held.tryAcquire(1, 10000));
    // 20,000 polls of watch 0 and 2,000 of watch 1, as the fleet hands them over (30 batches a second).
    qint64 most = 0;
    for (int b = 0; b < 100; ++b) {
        writer->offerSamples(batch(0, quint64(b) * 200 + 1, 200));
        writer->offerSamples(batch(1, quint64(b) * 20 + 1, 20));
        most = qMax(most, writer->queue().bytes());
    }
    QVERIFY2(most <= row * 500, qPrintable(QStringLiteral("%1 bytes queued, at most %2").arg(most).arg(row * 500)));
    QCOMPARE(writer->queue().bytes(), row * 500);
    QCOMPARE(dropping.size(), 0); // the writer has not seen it yet
    release.release();
    QTRY_COMPARE_WITH_TIMEOUT(caughtUp.size(), 1, 20000);
    QCOMPARE(dropping.size(), 1);
    QVERIFY2(dropping.first().first().toString().contains(QLatin1String("cannot keep up")), qPrintable(dropping.first().first().toString()));
    const quint64 total = caughtUp.first().first().toULongLong();
    QCOMPARE(total, quint64(22000 - 500));
    QVERIFY2(caughtUp.first().at(1).toString().contains(QStringLiteral("21500 rows dropped since ")), qPrintable(caughtUp.first().at(1).toString()));
    QVERIFY(!droppedRows.isEmpty());
    QMap<int, quint64> byWatch;
    for (const QList<QVariant> &args : std::as_const(droppedRows))
        byWatch[args.at(0).toInt()] = args.at(1).toULongLong();
    QCOMPARE(byWatch.value(0) + byWatch.value(1), total);
    QVERIFY(byWatch.value(1) > 0);

    // Caught up: more rows are written, nothing more is said.
    writer->offerSamples(batch(0, 30001, 10));
    writer->offerStopped();
    QTRY_COMPARE_WITH_TIMEOUT(drained.size(), 1, 20000);
    QCOMPARE(dropping.size(), 1);
    QCOMPARE(caughtUp.size(), 1);
    QCOMPARE(closed.size(), 1);
    QCOMPARE(closed.first().at(3).toULongLong(), total);
    QCOMPARE(closed.first().at(2).toULongLong(), total);
    thread.quit();
    thread.wait();

    // The rows kept are in the files, in order; the gap is noted in each watch's events file.
    const QStringList files = closed.first().at(1).toStringList();
    quint64 values = 0;
    int noted = 0;
    for (const QString &file : files) {
        const QStringList rows = lines(file);
        if (QFileInfo(file).fileName().contains(QLatin1String("-events-"))) {
            QCOMPARE(rows.size(), 3);
            QVERIFY2(rows.at(1).contains(QLatin1String(",overflow,warning,,,")), qPrintable(rows.at(1)));
            QVERIFY2(rows.at(2).contains(QLatin1String(",dropped,warning,,,")), qPrintable(rows.at(2)));
            QVERIFY2(rows.at(2).contains(QLatin1String("rows not logged since ")), qPrintable(rows.at(2)));
            ++noted;
        } else {
            values += quint64(rows.size() - 1);
        }
    }
    QCOMPARE(noted, 2);
    QCOMPARE(values, quint64(500 + 10));
}

void TestWatchLogWriter::nothingQueuedWhileLoggingIsOff()
{
    WatchLogWriter writer(1024);
    writer.offerStarted(twoWatches(QString()));
    writer.offerSamples(batch(0, 1, 100));
    QCOMPARE(writer.queue().size(), 1); // the start only
    QCOMPARE(writer.queue().bytes(), 0);
}

QTEST_GUILESS_MAIN(TestWatchLogWriter)
#include "tst_watchlogwriter.moc"
