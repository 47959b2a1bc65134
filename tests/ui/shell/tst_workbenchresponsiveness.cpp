// How long the GUI thread stops answering while the window polls the built-in simulator back to
// back (interval 0): the engine and the simulator run on threads of their own and the views take
// batched updates, so the event loop should keep turning. The figure is printed; the only
// assertion is a generous hang check (the project does not assert wall-clock times).
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "shell/mainwindow.h"
#include "shell/responsivenessprobe.h"
#include "traffic/trafficmonitor.h"
#include "compose/requestcomposer.h"
#include "decode/transactionview.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QTimer>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

#include <cstdio>

using namespace mbscope;

class TestWorkbenchResponsiveness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void backToBackPollKeepsTheEventLoopTurning();
};

void TestWorkbenchResponsiveness::initTestCase()
{
    guitest::isolateSettings();
}

void TestWorkbenchResponsiveness::backToBackPollKeepsTheEventLoopTurning()
{
    constexpr int kPollMs = 3000;
    constexpr int kTickMs = 2;
    // A hang detector only: anything below it is reported as a figure, not judged.
    constexpr qint64 kHangMs = 5000;

    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    quint64 transactions = 0;
    connect(window.controller(), &LinkController::transactionsFinished, this,
            [&transactions](const QList<Transaction> &batch) { transactions += quint64(batch.size()); });

    // A precise timer that notes the longest gap between two of its ticks: the longest time the
    // GUI thread's event loop did not come round.
    QElapsedTimer clock;
    qint64 lastNs = 0;
    qint64 longestGapNs = 0;
    quint64 ticks = 0;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(kTickMs);
    connect(&probe, &QTimer::timeout, this, [&] {
        const qint64 now = clock.nsecsElapsed();
        if (lastNs > 0)
            longestGapNs = qMax(longestGapNs, now - lastNs);
        lastNs = now;
        ++ticks;
    });

    // What a person waits for meanwhile: a menu opened, the traffic list moved to a random row,
    // each timed to its paint (ResponsivenessProbe, as MBSCOPE_RESPONSIVENESS_MS runs it).
    auto *traffic = window.findChild<TrafficMonitor *>();
    QVERIFY(traffic);
    ResponsivenessProbe asked(&window, traffic->view(), 100);

    QSignalSpy finished(window.controller(), &LinkController::pollFinished);
    window.composer()->intervalSpin()->setValue(0);
    window.composer()->countSpin()->setValue(0);
    clock.start();
    probe.start();
    window.composer()->togglePoll();
    QVERIFY(window.controller()->isPolling());
    QTest::qWait(kPollMs);
    window.composer()->togglePoll(); // stop
    QVERIFY(finished.wait(10000));
    probe.stop();

    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    const double stallMs = double(longestGapNs) / 1e6;
    std::printf("RESULT gui-responsiveness: longest event-loop stall %.2f ms during a back-to-back poll "
                "(%llu transactions in %.2f s, %.0f/s; %llu probe ticks of %d ms)\n",
                stallMs, static_cast<unsigned long long>(transactions), seconds, double(transactions) / seconds,
                static_cast<unsigned long long>(ticks), kTickMs);
    std::printf("RESULT gui-responsiveness: %s\n", qPrintable(asked.summary()));
    std::fflush(stdout);

    QVERIFY2(transactions > 20, "the poll must have run for the figure to mean anything");
    // The probe measures offscreen too: menus were opened and painted (a figure, not judged).
    QVERIFY2(!asked.menuMs().isEmpty(), qPrintable(asked.summary()));
    QVERIFY(ticks > 10);
    QVERIFY(window.answerView()->shown().has_value());
    QVERIFY2(longestGapNs / 1000000 < kHangMs, "the GUI thread hung during the poll");
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-after-poll.png")));
}

QTEST_MAIN(TestWorkbenchResponsiveness)
#include "tst_workbenchresponsiveness.moc"
