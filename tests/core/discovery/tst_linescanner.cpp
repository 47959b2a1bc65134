// LineScanner's progress and bounds (issue 18: every scan is bounded in count and time, shows
// progress and an estimate of the time left, and can be stopped) against the simulator on a socat
// pty pair. A pty carries every setting, so unit 1 answers on each and unit 5 (no such unit) is
// silent: trials counted of the plan known at the start, trials not needed counted as done, the
// first estimate made of the plan's timeouts, nothing left at the end; the time limit and stop()
// end the scan with what was tried. No assertion on how long anything took.

#include "discovery/linescanner.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestLineScanner : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void progressCountsThePlan();
    void withoutIdsThePlanHasBothPasses();
    void timeLimitEndsIt();
    void stopKeepsWhatWasTried();

private:
    [[nodiscard]] LineScanSettings settings(const QList<quint8> &units) const;
    // Runs a scan; every progress it emitted in *seen.
    std::optional<QList<LineTrial>> run(LineScanner &scanner, const LineScanSettings &s, QList<JobProgress> *seen);

    QTemporaryDir m_dir;
    QProcess m_socat;
    QString m_deviceEnd;
    QString m_scanEnd;
    std::unique_ptr<Simulator> m_sim;
};

void TestLineScanner::initTestCase()
{
    qRegisterMetaType<JobProgress>();
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        QSKIP("socat is not installed: no pty pair");
    QVERIFY(m_dir.isValid());
    m_deviceEnd = m_dir.filePath(QStringLiteral("device"));
    m_scanEnd = m_dir.filePath(QStringLiteral("scan"));
    m_socat.start(socat, {QStringLiteral("pty,raw,echo=0,link=") + m_deviceEnd, QStringLiteral("pty,raw,echo=0,link=") + m_scanEnd});
    QVERIFY2(m_socat.waitForStarted(5000), qPrintable(m_socat.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(m_deviceEnd) && QFileInfo::exists(m_scanEnd), 5000);
    m_sim = std::make_unique<Simulator>();
    SimUnit *unit = m_sim->addUnit(1);
    SimRange range;
    range.table = SimTable::HoldingRegisters;
    range.count = 10;
    QVERIFY(unit->addRange(range));
    QString error;
    QVERIFY2(m_sim->listen(QStringLiteral("rtu://") + m_deviceEnd, {}, &error), qPrintable(error));
}

void TestLineScanner::cleanupTestCase()
{
    m_sim.reset();
    if (m_socat.state() != QProcess::NotRunning) {
        m_socat.terminate();
        if (!m_socat.waitForFinished(5000))
            m_socat.kill();
    }
}

LineScanSettings TestLineScanner::settings(const QList<quint8> &units) const
{
    LineScanSettings s;
    s.url = *LinkUrl::parse(QStringLiteral("rtu://") + m_scanEnd).url;
    s.bauds = {9600, 19200};
    s.parities = {'E', 'N'};
    s.stopBits = {1};
    s.units = units;
    s.timeoutMs = 200;
    return s;
}

std::optional<QList<LineTrial>> TestLineScanner::run(LineScanner &scanner, const LineScanSettings &s, QList<JobProgress> *seen)
{
    const QMetaObject::Connection c =
        connect(&scanner, &LineScanner::progressChanged, this, [seen](const JobProgress &p) { seen->append(p); });
    std::optional<QList<LineTrial>> trials = scanner.run(s);
    disconnect(c);
    return trials;
}

// Ids 1 and 5 on four settings: 8 trials planned; unit 1 answers on each, so 5 is never asked.
void TestLineScanner::progressCountsThePlan()
{
    LineScanner scanner;
    QList<JobProgress> seen;
    const std::optional<QList<LineTrial>> trials = run(scanner, settings({1, 5}), &seen);
    QVERIFY(trials);
    QCOMPARE(scanner.end(), JobEnd::Completed);
    QCOMPARE(trials->size(), 4);
    for (const LineTrial &t : *trials)
        QVERIFY2(t.works(), qPrintable(t.settingText() + QLatin1Char(' ') + t.probe.summary()));
    // Before the first trial: every trial its timeout, 200 ms and the 15 characters of request
    // and answer at 11 bits (17 ms at 9600 baud, 8 ms at 19200), two parities, two ids.
    QCOMPARE(seen.first().done, 0);
    QCOMPARE(seen.first().total, 8);
    QCOMPARE(seen.first().remainingMs, qint64(2 * 2 * (217 + 208)));
    int done = 0;
    for (const JobProgress &p : std::as_const(seen)) {
        QCOMPARE(p.total, 8);
        QVERIFY2(p.done >= done, qPrintable(QStringLiteral("done went from %1 to %2").arg(done).arg(p.done)));
        done = p.done;
    }
    // Each setting's second id was not needed: counted with the first.
    QCOMPARE(seen.at(1).done, 2);
    QCOMPARE(seen.last().done, 8);
    QCOMPARE(seen.last().found, 4);
    QCOMPARE(seen.last().remainingMs, qint64(0));
}

// No ids: 1 on every setting, then 2-247 in case nothing answered; unit 1 answers, so the second
// pass is not needed and counts as done.
void TestLineScanner::withoutIdsThePlanHasBothPasses()
{
    LineScanner scanner;
    QList<JobProgress> seen;
    LineScanSettings s = settings({});
    s.bauds = {19200};
    const std::optional<QList<LineTrial>> trials = run(scanner, s, &seen);
    QVERIFY(trials);
    QCOMPARE(trials->size(), 2);
    for (const JobProgress &p : std::as_const(seen))
        QCOMPARE(p.total, 2 * 247);
    QCOMPARE(seen.last().done, 2 * 247);
    QCOMPARE(seen.last().remainingMs, qint64(0));
}

// Unit 5 is silent on every setting: 2 x 3 x 2 = 12 timeouts of over 200 ms, a limit of 700 ms.
void TestLineScanner::timeLimitEndsIt()
{
    LineScanner scanner;
    QList<JobProgress> seen;
    LineScanSettings s = settings({5});
    s.parities = {'E', 'N', 'O'};
    s.stopBits = {1, 2};
    s.maxDurationMs = 700;
    const std::optional<QList<LineTrial>> trials = run(scanner, s, &seen);
    QVERIFY(trials);
    QCOMPARE(scanner.end(), JobEnd::TimeLimit);
    QVERIFY(!trials->isEmpty() && trials->size() < 12);
    QCOMPARE(seen.last().total, 12);
    QCOMPARE(seen.last().done, int(trials->size()));
    QCOMPARE(seen.last().remainingMs, qint64(0));
    for (const JobProgress &p : std::as_const(seen))
        QVERIFY(p.remainingMs <= s.maxDurationMs);
}

void TestLineScanner::stopKeepsWhatWasTried()
{
    LineScanner scanner;
    QList<JobProgress> seen;
    connect(&scanner, &LineScanner::progressChanged, this, [&scanner](const JobProgress &p) {
        if (p.done == 2)
            scanner.stop();
    });
    const std::optional<QList<LineTrial>> trials = run(scanner, settings({5}), &seen);
    QVERIFY(trials);
    QCOMPARE(scanner.end(), JobEnd::Stopped);
    QCOMPARE(trials->size(), 2);
    QCOMPARE(seen.last().done, 2);
    QCOMPARE(seen.last().remainingMs, qint64(0));
}

QTEST_GUILESS_MAIN(TestLineScanner)
#include "tst_linescanner.moc"
