// Test plans from the window (PlanController, PlanPanel): a plan that passes and one that fails
// run against the built-in simulator (rosrao-gamma) through the connected link; every step is
// listed with what it expected and what came, each failure with why; the summary counts them;
// the JUnit XML written from the window holds the failure. QAbstractItemModelTester watches the
// results model; screenshots go to the test output.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "session/plancontroller.h"
#include "session/planpanel.h"
#include "session/planresultmodel.h"

#include "session/sessionreader.h"

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <QtWidgets/QTableView>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 30000;

// Unit 1's published settings (1050 at 0x0079, 250 at 0x007D) and a register outside the map
// (exception 02). failing: expects 251 at 0x007D and exception 01 instead.
QByteArray plan(bool failing)
{
    // Written with ' for " (moc does not read raw strings), put right before parsing.
    QString json = QStringLiteral(
        "{'format': 'mbscope-session', 'version': 1, 'name': '%1',"
        " 'target': {'url': 'tcp://127.0.0.1:1', 'timeoutMs': 500},"
        " 'plan': ["
        "  {'name': 'settings are the published ones',"
        "   'send': {'function': 3, 'unit': 1, 'address': '0x0079', 'quantity': 22},"
        "   'expect': {'fields': {'modbus.register_value@0x0079': 1050, 'modbus.register_value@0x007D': %2}}},"
        "  {'name': 'a register outside the map',"
        "   'send': {'function': 3, 'unit': 1, 'address': '0x0200', 'quantity': 1},"
        "   'expect': {'exception': %3}},"
        "  {'name': 'settle', 'wait': '10 ms'}"
        " ]}");
    json.replace(QLatin1Char('\''), QLatin1Char('"'));
    return json.arg(failing ? QStringLiteral("fails") : QStringLiteral("passes"))
        .arg(failing ? 251 : 250)
        .arg(failing ? 1 : 2)
        .toUtf8();
}

} // namespace

class TestPlanPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void runFromTheWindow_data();
    void runFromTheWindow();
    void refusesWithoutAPlan();
    void countsEveryRunOfTheExample();

private:
    QTemporaryDir m_dir;
    EmbeddedSimulator m_sim;
};

void TestPlanPanel::initTestCase()
{
    guitest::isolateSettings();
    QVERIFY(m_dir.isValid());
    const EmbeddedSimulator::Started started = m_sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
}

void TestPlanPanel::runFromTheWindow_data()
{
    QTest::addColumn<bool>("failing");
    QTest::addColumn<QStringList>("outcomes");
    QTest::addColumn<QStringList>("why");
    QTest::addColumn<QString>("shot");
    QTest::newRow("passes") << false << QStringList{QStringLiteral("PASS"), QStringLiteral("PASS"), QStringLiteral("PASS")}
                            << QStringList{QString(), QString(), QString()} << QStringLiteral("plan-passes.png");
    QTest::newRow("fails") << true << QStringList{QStringLiteral("FAIL"), QStringLiteral("FAIL"), QStringLiteral("PASS")}
                           << QStringList{QStringLiteral("modbus.register_value@0x007D is 250, expected 251"),
                                          QStringLiteral("expected exception 0x01"), QString()}
                           << QStringLiteral("plan-fails.png");
}

void TestPlanPanel::runFromTheWindow()
{
    QFETCH(bool, failing);
    QFETCH(QStringList, outcomes);
    QFETCH(QStringList, why);
    QFETCH(QString, shot);

    const SessionLoadResult loaded = SessionReader::parse(plan(failing), QStringLiteral("plan.mbscope.json"));
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    LinkController link;
    link.connectTo(m_sim.started().url); // the connected target, not the document's closed port
    PlanController controller(&link);
    QAbstractItemModelTester tester(controller.results(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    PlanPanel panel(&controller, [&loaded] { return *loaded.document; });
    panel.resize(1200, 260);
    const QString junit = m_dir.filePath(QStringLiteral("%1.xml").arg(QLatin1String(QTest::currentDataTag())));
    panel.setFileChooser([junit] { return junit; });
    // Before a run, the panel says what the open session's plan holds.
    QVERIFY2(panel.summaryText().contains(QLatin1String("has 3 step(s)")), qPrintable(panel.summaryText()));

    QSignalSpy finished(&controller, &PlanController::finished);
    panel.run();
    QVERIFY(controller.isRunning());
    QVERIFY(finished.wait(kWaitMs));
    QCOMPARE(finished.at(0).at(1).toBool(), !failing);

    PlanResultModel *model = controller.results();
    QCOMPARE(model->rowCount(), outcomes.size());
    for (int row = 0; row < model->rowCount(); ++row) {
        QCOMPARE(model->index(row, PlanResultModel::OutcomeColumn).data().toString(), outcomes.at(row));
        const QString because = model->index(row, PlanResultModel::WhyColumn).data().toString();
        if (why.at(row).isEmpty())
            QVERIFY2(because.isEmpty(), qPrintable(because));
        else
            QVERIFY2(because.contains(why.at(row)), qPrintable(because));
    }
    // What was expected, from the plan; what came, from the exchange.
    QCOMPARE(model->index(0, PlanResultModel::StepColumn).data().toString(), QStringLiteral("settings are the published ones"));
    QCOMPARE(model->index(0, PlanResultModel::ExpectedColumn).data().toString(),
             QStringLiteral("modbus.register_value@0x0079 = 1050, modbus.register_value@0x007D = %1").arg(failing ? 251 : 250));
    QCOMPARE(model->index(1, PlanResultModel::ExpectedColumn).data().toString(),
             QStringLiteral("exception 0x%1").arg(failing ? QStringLiteral("01") : QStringLiteral("02")));
    QCOMPARE(model->index(2, PlanResultModel::ExpectedColumn).data().toString(), QStringLiteral("waits 10 ms"));
    QVERIFY2(model->index(0, PlanResultModel::CameColumn).data().toString().startsWith(QStringLiteral("sent 01 03 00 79 00 16")),
             qPrintable(model->index(0, PlanResultModel::CameColumn).data().toString()));

    const QString summary = panel.summaryText();
    QVERIFY2(summary.startsWith(failing ? QStringLiteral("Failed. Steps: 3; passed 1, failed 2, errors 0")
                                   : QStringLiteral("Passed. Steps: 3; passed 3, failed 0, errors 0")),
             qPrintable(summary));
    QVERIFY2(summary.contains(m_sim.started().url.toString()), qPrintable(summary));

    panel.exportJUnit();
    QFile xml(junit);
    QVERIFY2(xml.open(QIODevice::ReadOnly), qPrintable(junit));
    const QByteArray text = xml.readAll();
    QCOMPARE(text.count("<testcase "), 3);
    QCOMPARE(text.count("<failure"), failing ? 2 : 0);
    QVERIFY(guitest::saveShot(&panel, shot));
}

void TestPlanPanel::refusesWithoutAPlan()
{
    LinkController link;
    PlanController controller(&link);
    QString error;
    SessionDocument empty;
    QVERIFY(!controller.run(empty, &error));
    QVERIFY2(error.contains(QStringLiteral("no test plan")), qPrintable(error));
    const SessionLoadResult loaded = SessionReader::parse(plan(false), QStringLiteral("plan.mbscope.json"));
    QVERIFY(loaded.ok());
    SessionDocument noTarget = *loaded.document;
    noTarget.target.url.clear();
    QVERIFY(!controller.run(noTarget, &error));
    QVERIFY2(error.contains(QStringLiteral("Connect to a device")), qPrintable(error));
    QVERIFY(!controller.exportJUnit(m_dir.filePath(QStringLiteral("none.xml")), &error));
    QVERIFY2(error.contains(QStringLiteral("Run the plan")), qPrintable(error));

    // A session without a plan is said to have none, and a session opened later is looked at again.
    SessionDocument shown = empty;
    PlanPanel panel(&controller, [&shown] { return shown; });
    QVERIFY2(panel.summaryText().contains(QLatin1String("no test plan")), qPrintable(panel.summaryText()));
    shown = *loaded.document;
    shown.name = QStringLiteral("acceptance");
    panel.showDocumentHint();
    QVERIFY2(panel.summaryText().contains(QLatin1String("The plan of acceptance has 3 step(s)")), qPrintable(panel.summaryText()));
}

void TestPlanPanel::countsEveryRunOfTheExample()
{
    // The shipped example: 11 steps in the document, one of them a repeat of 2 steps 3 times, so
    // 16 runs; the window says 16 as mbscope run does ("16 steps"), and a run stopped at once
    // reports each of the 16 as skipped (a stop is not a failure).
    QFile example(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../docs/examples/rosrao-gamma.mbscope.json"));
    QVERIFY(example.open(QIODevice::ReadOnly));
    const SessionLoadResult loaded = SessionReader::parse(example.readAll(), example.fileName());
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(loaded.document->plan.size(), std::size_t(11));
    LinkController link;
    link.connectTo(m_sim.started().url);
    PlanController controller(&link);
    PlanPanel panel(&controller, [&loaded] { return *loaded.document; });
    QVERIFY2(panel.summaryText().contains(QLatin1String("has 16 step(s)")), qPrintable(panel.summaryText()));

    QSignalSpy finished(&controller, &PlanController::finished);
    panel.run();
    controller.stop();
    QVERIFY(finished.wait(kWaitMs));
    QVERIFY(controller.lastResult().has_value());
    const PlanResult &result = *controller.lastResult();
    QCOMPARE(result.steps.size(), qsizetype(16));
    QCOMPARE(result.planned, 16);
    QCOMPARE(result.count(StepResult::Outcome::Failed), 0);
    QCOMPARE(controller.results()->rowCount(), 16);
    QVERIFY2(panel.summaryText().contains(QLatin1String("Steps: 16;")), qPrintable(panel.summaryText()));
}

QTEST_MAIN(TestPlanPanel)
#include "tst_planpanel.moc"
