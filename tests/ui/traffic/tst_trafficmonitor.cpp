// TrafficMonitor, offscreen: selecting a row emits the frame with its request or answer, the
// filter controls, pause and resume, clear, find (hex and text, Enter and F3), following the
// newest row; paired with a DecodeView as the window docks them; a million rows appended while
// the list is shown (times printed, not asserted); screenshots.
#include "decode/decodeview.h"
#include "guitestsupport.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"

#include <QtCore/QElapsedTimer>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolButton>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

const QByteArray kRosRaoRequest = QByteArray::fromHex("01 03 00 79 00 16 15 DD");
const QByteArray kTutorialRequest = QByteArray::fromHex("07 03 00 C8 00 04 C5 91");
const QByteArray kTutorialResponse = QByteArray::fromHex("07 03 08 00 07 00 06 00 05 00 04 64 5D");
const QByteArray kException = QByteArray::fromHex("07 83 02 B1 33");

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

// A poll of the tutorial's unit 7 with a timeout and an exception, then a stray frame.
QList<TrafficFrame> samplePoll(quint64 firstId = 1, qint64 startNs = 0)
{
    QList<TrafficFrame> frames;
    const qint64 ms = 1'000'000;
    for (quint64 i = 0; i < 10; ++i) {
        const quint64 id = firstId + i;
        const qint64 t = startNs + qint64(i) * 500 * ms;
        frames << frame(t, TrafficDirection::Out, TrafficVerdict::Sent, id, kTutorialRequest);
        if (i == 3)
            frames << frame(t + 1000 * ms, TrafficDirection::In, TrafficVerdict::Timeout, id, {});
        else if (i == 6)
            frames << frame(t + 4 * ms, TrafficDirection::In, TrafficVerdict::Exception, id, kException);
        else
            frames << frame(t + 7 * ms + qint64(i) * 100'000, TrafficDirection::In, TrafficVerdict::Ok, id, kTutorialResponse);
    }
    frames << frame(startNs + 5200 * ms, TrafficDirection::In, TrafficVerdict::Unsolicited, 0, QByteArray::fromHex("01 03 02 00 2A 38 5B"));
    return frames;
}

} // namespace

class TestTrafficMonitor : public QObject
{
    Q_OBJECT

private:
    TrafficMonitor *m_monitor = nullptr;
    std::unique_ptr<QAbstractItemModelTester> m_tester;

    template<typename T>
    T *child(const char *name) const
    {
        return m_monitor->findChild<T *>(QLatin1String(name));
    }

private Q_SLOTS:
    void init();
    void cleanup();
    void selectingARowEmitsTheExchange();
    void filterControls_data();
    void filterControls();
    void filterKeepsTheSelection();
    void pauseAndResume();
    void clearEmptiesTheList();
    void findWithEnterAndF3();
    void findReportsNothingFound();
    void followsTheNewestRow();
    void decodeViewShowsTheSelection();
    void millionRowsShown();
};

void TestTrafficMonitor::init()
{
    m_monitor = new TrafficMonitor;
    m_tester = std::make_unique<QAbstractItemModelTester>(m_monitor->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    m_monitor->model()->setLinkName(0, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    m_monitor->resize(1200, 400);
    m_monitor->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_monitor));
}

void TestTrafficMonitor::cleanup()
{
    m_tester.reset();
    delete m_monitor;
    m_monitor = nullptr;
}

void TestTrafficMonitor::selectingARowEmitsTheExchange()
{
    m_monitor->appendFrames(samplePoll());
    QCOMPARE(m_monitor->model()->rowCount(), 21);
    QSignalSpy selected(m_monitor, &TrafficMonitor::frameSelected);
    // A click on the answer of the second poll cycle.
    QTableView *view = m_monitor->view();
    view->scrollToTop();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(m_monitor->model()->index(3, 1)).center());
    QCOMPARE(selected.size(), 1);
    auto e = selected.at(0).at(0).value<FrameExchange>();
    QCOMPARE(e.selected, TrafficDirection::In);
    QCOMPARE(e.response, kTutorialResponse);
    QCOMPARE(e.request, kTutorialRequest);
    QCOMPARE(e.verdict, TrafficVerdict::Ok);
    QCOMPARE(e.latencyNs, 7'100'000);
    QCOMPARE(e.framing, Framing::Rtu);
    // Down to the next request with the keyboard.
    QTest::keyClick(view, Qt::Key_Down);
    QCOMPARE(selected.size(), 2);
    e = selected.at(1).at(0).value<FrameExchange>();
    QCOMPARE(e.selected, TrafficDirection::Out);
    QCOMPARE(e.request, kTutorialRequest);
    QCOMPARE(e.response, kTutorialResponse);
}

void TestTrafficMonitor::filterControls_data()
{
    QTest::addColumn<int>("unit");
    QTest::addColumn<QString>("function"); // the combo's text starts with it, empty: any
    QTest::addColumn<int>("direction");    // combo index
    QTest::addColumn<QString>("verdict");  // combo text
    QTest::addColumn<int>("rows");

    QTest::newRow("all") << -1 << QString() << 0 << QStringLiteral("any") << 21;
    QTest::newRow("unit 7 (a timeout frame has its request's)") << 7 << QString() << 0 << QStringLiteral("any") << 20;
    QTest::newRow("unit 1") << 1 << QString() << 0 << QStringLiteral("any") << 1;
    QTest::newRow("function 0x03 and its exception") << -1 << QStringLiteral("0x03") << 0 << QStringLiteral("any") << 21;
    QTest::newRow("function 0x10") << -1 << QStringLiteral("0x10") << 0 << QStringLiteral("any") << 0;
    QTest::newRow("out") << -1 << QString() << 1 << QStringLiteral("any") << 10;
    QTest::newRow("in") << -1 << QString() << 2 << QStringLiteral("any") << 11;
    QTest::newRow("problems only") << -1 << QString() << 0 << QStringLiteral("problems only") << 3;
    QTest::newRow("timeout") << -1 << QString() << 0 << QStringLiteral("timeout") << 1;
    QTest::newRow("unit 7, in, ok") << 7 << QString() << 2 << QStringLiteral("ok") << 8;
}

void TestTrafficMonitor::filterControls()
{
    QFETCH(int, unit);
    QFETCH(QString, function);
    QFETCH(int, direction);
    QFETCH(QString, verdict);
    QFETCH(int, rows);

    m_monitor->appendFrames(samplePoll());
    child<QSpinBox>("unitFilter")->setValue(unit);
    auto *functions = child<QComboBox>("functionFilter");
    functions->setCurrentIndex(function.isEmpty() ? 0 : functions->findText(function, Qt::MatchStartsWith));
    QVERIFY(functions->currentIndex() >= 0);
    child<QComboBox>("directionFilter")->setCurrentIndex(direction);
    auto *verdicts = child<QComboBox>("verdictFilter");
    verdicts->setCurrentIndex(verdicts->findText(verdict));
    QVERIFY(verdicts->currentIndex() >= 0);
    QCOMPARE(m_monitor->model()->rowCount(), rows);
    const QString status = child<QLabel>("statusLabel")->text();
    QVERIFY2(status.startsWith(QStringLiteral("21 frames")), qPrintable(status));
    QCOMPARE(status.contains(QStringLiteral("shown")), rows != 21);
    // New frames pass the same filter.
    m_monitor->appendFrames(samplePoll(100, 10'000'000'000));
    QCOMPARE(m_monitor->model()->rowCount(), 2 * rows);
}

void TestTrafficMonitor::filterKeepsTheSelection()
{
    m_monitor->appendFrames(samplePoll());
    m_monitor->selectRow(13); // the exception
    QCOMPARE(m_monitor->model()->data(m_monitor->model()->index(13, TrafficModel::VerdictColumn)).toString(),
             QStringLiteral("exception"));
    auto *verdicts = child<QComboBox>("verdictFilter");
    verdicts->setCurrentIndex(verdicts->findText(QStringLiteral("problems only")));
    QCOMPARE(m_monitor->model()->rowCount(), 3);
    QCOMPARE(m_monitor->currentRow(), 1);
    QCOMPARE(m_monitor->model()->exchangeAt(1).response, kException);
}

void TestTrafficMonitor::pauseAndResume()
{
    auto *pause = child<QToolButton>("pauseButton");
    m_monitor->appendFrames(samplePoll());
    QTest::mouseClick(pause, Qt::LeftButton);
    QVERIFY(m_monitor->isPaused());
    QCOMPARE(pause->text(), QStringLiteral("Resume"));
    m_monitor->appendFrames(samplePoll(100, 10'000'000'000));
    QCOMPARE(m_monitor->model()->rowCount(), 21);
    QVERIFY(child<QLabel>("statusLabel")->text().contains(QStringLiteral("paused: 21 new frames held")));
    QTest::mouseClick(pause, Qt::LeftButton);
    QVERIFY(!m_monitor->isPaused());
    QCOMPARE(m_monitor->model()->rowCount(), 42);
    QCOMPARE(pause->text(), QStringLiteral("Pause"));
    QVERIFY(!child<QLabel>("statusLabel")->text().contains(QStringLiteral("paused")));
}

void TestTrafficMonitor::clearEmptiesTheList()
{
    m_monitor->appendFrames(samplePoll());
    m_monitor->selectRow(2);
    QTest::mouseClick(child<QToolButton>("clearButton"), Qt::LeftButton);
    QCOMPARE(m_monitor->model()->rowCount(), 0);
    QCOMPARE(m_monitor->currentRow(), -1);
    QCOMPARE(child<QLabel>("statusLabel")->text(), QStringLiteral("0 frames"));
}

void TestTrafficMonitor::findWithEnterAndF3()
{
    m_monitor->appendFrames(samplePoll());
    auto *search = child<QLineEdit>("searchEdit");
    // Ctrl+F puts the cursor in the find field.
    m_monitor->view()->setFocus();
    QTest::keyClick(m_monitor->view(), Qt::Key_F, Qt::ControlModifier);
    QVERIFY(search->hasFocus());
    QTest::keyClicks(search, QStringLiteral("07 83"));
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(m_monitor->currentRow(), 13);
    search->setText(QStringLiteral("c5 91")); // the request's CRC, lower case
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(m_monitor->currentRow(), 14);
    QTest::keyClick(search, Qt::Key_F3);
    QCOMPARE(m_monitor->currentRow(), 16);
    QTest::keyClick(search, Qt::Key_F3, Qt::ShiftModifier);
    QCOMPARE(m_monitor->currentRow(), 14);
    search->setText(QStringLiteral("unsolicited"));
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(m_monitor->currentRow(), 20);
}

void TestTrafficMonitor::findReportsNothingFound()
{
    m_monitor->appendFrames(samplePoll());
    m_monitor->selectRow(4);
    auto *search = child<QLineEdit>("searchEdit");
    search->setText(QStringLiteral("DE AD"));
    QTest::keyClick(search, Qt::Key_Return);
    QCOMPARE(m_monitor->currentRow(), 4);
    const QString status = child<QLabel>("statusLabel")->text();
    QVERIFY2(status.contains(QStringLiteral("No frame shown matches \u201CDE AD\u201D")), qPrintable(status));
}

void TestTrafficMonitor::followsTheNewestRow()
{
    QScrollBar *bar = m_monitor->view()->verticalScrollBar();
    for (int i = 0; i < 5; ++i)
        m_monitor->appendFrames(samplePoll(quint64(100 * i), qint64(i) * 10'000'000'000));
    QCoreApplication::processEvents();
    QVERIFY(bar->maximum() > 0);
    QCOMPARE(bar->value(), bar->maximum());
    // Scrolled up, the view stays where the user put it.
    bar->setValue(0);
    m_monitor->appendFrames(samplePoll(1000, 60'000'000'000));
    QCoreApplication::processEvents();
    QCOMPARE(bar->value(), 0);
    // Back at the end, it follows again.
    bar->setValue(bar->maximum());
    m_monitor->appendFrames(samplePoll(2000, 70'000'000'000));
    QCoreApplication::processEvents();
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY(guitest::saveShot(m_monitor, QStringLiteral("trafficmonitor.png")));
}

// As the window docks them: the traffic list above, the decode view below, wired by one connect.
void TestTrafficMonitor::decodeViewShowsTheSelection()
{
    QSplitter pair(Qt::Vertical);
    auto *monitor = new TrafficMonitor(&pair);
    auto *decode = new DecodeView(&pair);
    QObject::connect(monitor, &TrafficMonitor::frameSelected, decode, &DecodeView::showExchange);
    monitor->model()->setLinkName(0, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    monitor->appendFrames(samplePoll());
    pair.resize(1200, 900);
    pair.show();
    QVERIFY(QTest::qWaitForWindowExposed(&pair));
    monitor->selectRow(13);
    QCOMPARE(decode->responseDissection().fields.frame(), kException);
    QCOMPARE(decode->requestDissection().fields.frame(), kTutorialRequest);
    QCOMPARE(decode->exchange().verdict, TrafficVerdict::Exception);
    monitor->selectRow(7);
    QCOMPARE(decode->exchange().verdict, TrafficVerdict::Timeout);
    QVERIFY(decode->responseDissection().fields.isEmpty());
    monitor->selectRow(5);
    QVERIFY(guitest::saveShot(&pair, QStringLiteral("traffic-and-decode.png")));
}

// Appending a million rows in engine-sized batches while the list is shown and following, with
// the event loop run after each batch as the window would; the figures are printed.
void TestTrafficMonitor::millionRowsShown()
{
    m_tester.reset(); // it would walk every row on each reset
    constexpr int kBatches = 500;
    constexpr int kBatchSize = 2000;
    QElapsedTimer timer;
    qint64 worstBatchNs = 0;
    qint64 firstTenNs = 0; // batches near the start and near a million rows: does a batch cost grow?
    qint64 lastTenNs = 0;
    timer.start();
    for (int b = 0; b < kBatches; ++b) {
        QList<TrafficFrame> batch;
        batch.reserve(kBatchSize);
        for (int i = 0; i < kBatchSize; i += 2) {
            const auto id = quint64(b) * kBatchSize + quint64(i) + 1;
            const qint64 t = qint64(id) * 1'000'000;
            batch << frame(t, TrafficDirection::Out, TrafficVerdict::Sent, id, kTutorialRequest)
                  << frame(t + 800'000, TrafficDirection::In, TrafficVerdict::Ok, id, kTutorialResponse);
        }
        QElapsedTimer one;
        one.start();
        m_monitor->appendFrames(batch);
        QCoreApplication::processEvents(); // the repaint that follows
        const qint64 batchNs = one.nsecsElapsed();
        worstBatchNs = std::max(worstBatchNs, batchNs);
        if (b < 10)
            firstTenNs += batchNs;
        else if (b >= kBatches - 10)
            lastTenNs += batchNs;
    }
    const qint64 totalNs = timer.nsecsElapsed();
    QCOMPARE(m_monitor->model()->rowCount(), kBatches * kBatchSize);
    QScrollBar *bar = m_monitor->view()->verticalScrollBar();
    QCOMPARE(bar->value(), bar->maximum());
    timer.start();
    auto *verdicts = child<QComboBox>("verdictFilter");
    verdicts->setCurrentIndex(verdicts->findText(QStringLiteral("problems only")));
    QCoreApplication::processEvents();
    const qint64 filterNs = timer.nsecsElapsed();
    QCOMPARE(m_monitor->model()->rowCount(), 0);
    verdicts->setCurrentIndex(0);
    timer.start();
    m_monitor->selectRow(kBatches * kBatchSize / 2);
    QCoreApplication::processEvents();
    const qint64 jumpNs = timer.nsecsElapsed();
    timer.start();
    const QPixmap shot = m_monitor->grab();
    const qint64 paintNs = timer.nsecsElapsed();
    QVERIFY(!shot.isNull());
    qInfo("traffic monitor, %d rows shown in %d batches of %d: %.1f ms in all, a batch with its repaint: first ten %.2f ms, "
          "last ten %.2f ms, worst %.2f ms",
          kBatches * kBatchSize, kBatches, kBatchSize, double(totalNs) / 1e6, double(firstTenNs) / 1e7, double(lastTenNs) / 1e7,
          double(worstBatchNs) / 1e6);
    qInfo("problems-only filter over them %.1f ms; jump to the middle row %.2f ms; paint the widget %.2f ms; model memory %.1f MB",
          double(filterNs) / 1e6, double(jumpNs) / 1e6, double(paintNs) / 1e6, double(m_monitor->model()->memoryBytes()) / 1e6);
    QVERIFY(guitest::saveShot(m_monitor, QStringLiteral("trafficmonitor-million.png")));
}

QTEST_MAIN(TestTrafficMonitor)
#include "tst_trafficmonitor.moc"
