// The traffic list over a long poll (issue 31): memory holds its newest frames only, the rest
// goes to the archive on disk and stays listed: the first transaction can still be scrolled to,
// shown with its answer, found with the find field, filtered and saved. Where the archive
// cannot be written the oldest frames are dropped and the status line says why.
#include "guitestsupport.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "traffic/trafficsaver.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QTemporaryDir>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// The first transaction: the RosRao read of unit 1 and its answer; all the others: the
// tutorial's read of unit 7, so that the first is the only frame of unit 1.
const QByteArray kFirstRequest = QByteArray::fromHex("01 03 00 79 00 16 15 DD");
const QByteArray kFirstAnswer = QByteArray::fromHex("01 03 04 00 2A 00 07 DA 31");
const QByteArray kRequest = QByteArray::fromHex("07 03 00 C8 00 04 C5 91");
const QByteArray kAnswer = QByteArray::fromHex("07 03 08 00 07 00 06 00 05 00 04 64 5D");

constexpr int kMemoryRows = 1000;

TrafficFrame frame(qint64 tNs, TrafficDirection direction, TrafficVerdict verdict, quint64 id, const QByteArray &bytes)
{
    TrafficFrame f;
    f.tNs = tNs;
    f.direction = direction;
    f.verdict = verdict;
    f.transactionId = id;
    f.bytes = bytes;
    return f;
}

// Transactions first .. first + count - 1, 1 ms apart, answered 0.8 ms later; transaction 1 is
// the RosRao read.
QList<TrafficFrame> poll(quint64 first, int count)
{
    QList<TrafficFrame> frames;
    for (quint64 id = first; id < first + quint64(count); ++id) {
        const qint64 t = qint64(id) * 1'000'000;
        frames << frame(t, TrafficDirection::Out, TrafficVerdict::Sent, id, id == 1 ? kFirstRequest : kRequest)
               << frame(t + 800'000, TrafficDirection::In, TrafficVerdict::Ok, id, id == 1 ? kFirstAnswer : kAnswer);
    }
    return frames;
}

} // namespace

class TestTrafficMemory : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void firstTransactionStaysReachable();
    void memoryStaysBounded();
    void unwritableArchiveDropsAndSays();
};

void TestTrafficMemory::firstTransactionStaysReachable()
{
    QTemporaryDir cache;
    TrafficMonitor monitor;
    TrafficModel *model = monitor.model();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model->setArchiveFolder(cache.path());
    model->setRowLimit(kMemoryRows);
    model->setLinkName(0, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    monitor.resize(1200, 400);
    monitor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&monitor));
    constexpr int kTransactions = 10'000;
    for (quint64 first = 1; first <= kTransactions; first += 250) {
        monitor.appendFrames(poll(first, 250));
        QCoreApplication::processEvents();
    }
    // Every frame listed, most of them from disk.
    QCOMPARE(model->rowCount(), 2 * kTransactions);
    QCOMPARE(model->frameCount(), 2 * kTransactions);
    QCOMPARE(model->droppedCount(), quint64(0));
    QVERIFY(model->log().size() <= quint64(kMemoryRows));
    QCOMPARE(model->archivedCount(), quint64(2 * kTransactions) - model->log().size());
    QVERIFY2(model->archiveProblem().isEmpty(), qPrintable(model->archiveProblem()));

    // Scrolled to the top, the first row shows the first request; selecting it gives its answer.
    QTableView *view = monitor.view();
    view->scrollToTop();
    QCOMPARE(model->index(0, TrafficModel::NumberColumn).data().toString(), QStringLiteral("1"));
    QCOMPARE(model->index(0, TrafficModel::BytesColumn).data().toString(), QStringLiteral("01 03 00 79 00 16 15 DD"));
    QCOMPARE(model->index(0, TrafficModel::UnitColumn).data().toString(), QStringLiteral("1"));
    QCOMPARE(model->index(1, TrafficModel::LatencyColumn).data().toString(), QStringLiteral("800.0 \u00B5s"));
    QSignalSpy selected(&monitor, &TrafficMonitor::frameSelected);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(model->index(0, 1)).center());
    QCOMPARE(selected.size(), 1);
    const auto first = selected.at(0).at(0).value<FrameExchange>();
    QCOMPARE(first.request, kFirstRequest);
    QCOMPARE(first.response, kFirstAnswer);
    QCOMPARE(first.latencyNs, 800'000);
    QVERIFY(guitest::saveShot(&monitor, QStringLiteral("traffic-archived-top.png")));

    // Found from the newest row: the find field wraps round to it, through the archive.
    monitor.selectRow(model->rowCount() - 1);
    auto *search = monitor.findChild<QLineEdit *>(QStringLiteral("searchEdit"));
    QVERIFY(search);
    search->setText(QStringLiteral("15 DD"));
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(monitor.currentRow(), 0);
    search->setText(QStringLiteral("DA 31"));
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(monitor.currentRow(), 1);

    // Filtered by unit 1: the two archived frames of the first transaction.
    auto *unit = monitor.findChild<QSpinBox *>(QStringLiteral("unitFilter"));
    unit->setValue(1);
    QCOMPARE(model->rowCount(), 2);
    QCOMPARE(model->index(0, TrafficModel::BytesColumn).data().toString(), QStringLiteral("01 03 00 79 00 16 15 DD"));
    unit->setValue(-1);
    QCOMPARE(model->rowCount(), 2 * kTransactions);

    // Saved whole: the archive's frames first, then memory's, in order.
    QTemporaryDir out;
    const QString path = out.filePath(QStringLiteral("all.mbscope.journal"));
    const TrafficSaver::Result saved = TrafficSaver::save(*model, false, path, TrafficFormat::Journal, QString());
    QVERIFY2(saved.ok, qPrintable(saved.error));
    QList<TrafficFrame> read;
    const TrafficJournalRecovery recovery = TrafficJournalReader::readAll(path, &read);
    QVERIFY2(recovery.isClean(), qPrintable(recovery.message));
    QCOMPARE(read.size(), 2 * kTransactions);
    QCOMPARE(read.first().bytes, kFirstRequest);
    QCOMPARE(read.at(1).bytes, kFirstAnswer);
    QCOMPARE(read.last().bytes, kAnswer);

    // Clear forgets the archive too.
    model->clear();
    QCOMPARE(model->rowCount(), 0);
    QCOMPARE(model->archivedCount(), quint64(0));
}

// The model's memory after 10,000 and after 40,000 transactions: the same, within a batch's
// worth (the list's memory is bounded by its row limit, not by the poll's length).
void TestTrafficMemory::memoryStaysBounded()
{
    QTemporaryDir cache;
    TrafficModel model;
    model.setArchiveFolder(cache.path());
    model.setRowLimit(kMemoryRows);
    model.setLinkName(0, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    quint64 id = 1;
    for (; id <= 10'000; id += 500)
        model.appendLinkFrames(poll(id, 500), QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    const std::size_t after10k = model.memoryBytes();
    for (; id <= 40'000; id += 500)
        model.appendLinkFrames(poll(id, 500), QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    const std::size_t after40k = model.memoryBytes();
    qInfo("traffic list memory: %.1f KiB after 10,000 transactions, %.1f KiB after 40,000", double(after10k) / 1024.0,
          double(after40k) / 1024.0);
    QCOMPARE(model.rowCount(), 80'000);
    QVERIFY2(after40k < after10k + 64 * 1024, qPrintable(QStringLiteral("%1 then %2 bytes").arg(after10k).arg(after40k)));
    // Without the archive the same limit drops the oldest instead, and counts them.
    TrafficModel dropping;
    dropping.setRowLimit(kMemoryRows);
    dropping.appendLinkFrames(poll(1, 5000), QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    QVERIFY(dropping.rowCount() <= kMemoryRows);
    QCOMPARE(dropping.droppedCount() + quint64(dropping.rowCount()), quint64(10'000));
}

void TestTrafficMemory::unwritableArchiveDropsAndSays()
{
    QTemporaryDir dir;
    QFile plain(dir.filePath(QStringLiteral("plain")));
    QVERIFY(plain.open(QIODevice::WriteOnly));
    plain.close();
    TrafficMonitor monitor;
    TrafficModel *model = monitor.model();
    model->setArchiveFolder(dir.filePath(QStringLiteral("plain/cache")));
    model->setRowLimit(kMemoryRows);
    monitor.appendFrames(poll(1, 2000));
    QVERIFY(model->rowCount() <= kMemoryRows);
    QVERIFY(model->droppedCount() > 0);
    QVERIFY(!model->archiveProblem().isEmpty());
    const QString status = monitor.findChild<QLabel *>(QStringLiteral("statusLabel"))->text();
    QVERIFY2(status.contains(QStringLiteral("oldest dropped from the list")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("older frames are no longer kept on disk")) && status.contains(QStringLiteral("plain/cache")),
             qPrintable(status));
}

QTEST_MAIN(TestTrafficMemory)
#include "tst_trafficmemory.moc"
