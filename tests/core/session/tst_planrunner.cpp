// PlanRunner against the rosrao-gamma profile served in-process: for each kind of expectation
// (exact bytes, field values, field ranges, exception code, no answer, a plain send, an expect
// step) a plan that passes and one that fails with the reason a user must see; poll bounds that
// hold and do not; the JUnit report read back with QXmlStreamReader; a link error.

#include "rosraosim.h"

#include "session/junitreport.h"
#include "session/planrunner.h"
#include "session/sessionreader.h"

#include <QtCore/QXmlStreamReader>
#include <QtNetwork/QTcpServer>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// A document of the given requests and plan steps (JSON text), which must load.
SessionDocument document(const QString &requests, const QString &plan)
{
    const QString json = QStringLiteral(R"({"format": "mbscope-session", "version": 1, "name": "plan test",
        "requests": [%1], "plan": [%2]})").arg(requests, plan);
    const SessionLoadResult r = SessionReader::parse(json.toUtf8(), QStringLiteral("test.mbscope.json"));
    if (!r.ok())
        qFatal("test document refused: %s", qPrintable(r.errorText()));
    return *r.document;
}

const QString kRequests = QStringLiteral(
    R"({"name": "read all", "hex": "01 03 00 79 00 16 15 DD"},)"
    R"({"name": "write 250", "function": 6, "address": "0x007D", "values": [250]},)"
    R"({"name": "outside", "function": 3, "address": "0x0200", "quantity": 1},)"
    R"({"name": "broadcast", "hex": "00 06 00 7D 00 FA 98 40"})");

struct JUnitCase {
    QString name;
    QString classname;
    QString element; // "", "failure", "error", "skipped"
    QString message;
};

struct JUnitSuite {
    QMap<QString, QString> attributes;
    QList<JUnitCase> cases;
    QString error;
};

JUnitSuite readJUnit(const QByteArray &xml)
{
    JUnitSuite suite;
    QXmlStreamReader reader(xml);
    while (!reader.atEnd()) {
        reader.readNext();
        if (!reader.isStartElement())
            continue;
        const auto name = reader.name();
        if (name == QLatin1String("testsuite")) {
            for (const QXmlStreamAttribute &a : reader.attributes())
                suite.attributes.insert(a.name().toString(), a.value().toString());
        } else if (name == QLatin1String("testcase")) {
            JUnitCase c;
            c.name = reader.attributes().value(QLatin1String("name")).toString();
            c.classname = reader.attributes().value(QLatin1String("classname")).toString();
            suite.cases.append(c);
        } else if ((name == QLatin1String("failure") || name == QLatin1String("error") || name == QLatin1String("skipped"))
                   && !suite.cases.isEmpty()) {
            suite.cases.last().element = name.toString();
            suite.cases.last().message = reader.attributes().value(QLatin1String("message")).toString();
        }
    }
    if (reader.hasError())
        suite.error = reader.errorString();
    return suite;
}

} // namespace

class TestPlanRunner : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void expectations_data();
    void expectations();
    void pollBounds_data();
    void pollBounds();
    void junitReport();
    void linkError();
    void interruptedWaitIsSkipped();
    void shippedExample();

private:
    sessiontest::RosraoSim m_sim;
};

void TestPlanRunner::initTestCase()
{
    QString error;
    QVERIFY2(m_sim.start(&error), qPrintable(error));
}

void TestPlanRunner::expectations_data()
{
    QTest::addColumn<QString>("plan");
    QTest::addColumn<bool>("passes");
    QTest::addColumn<QString>("reason"); // the last step's first reason

    // Exact bytes: the echo of Write Single Register (V1.1b3 6.6).
    QTest::newRow("bytes pass") << R"({"name": "s", "send": "write 250", "expect": {"bytes": "01 06 00 7D 00 FA 99 91"}})"
                                << true << "answer is 01 06 00 7D 00 FA 99 91, as expected";
    QTest::newRow("bytes fail") << R"({"name": "s", "send": "write 250", "expect": {"bytes": "01 06 00 7D 00 FB 58 51"}})"
                                << false
                                << "answer is 01 06 00 7D 00 FA 99 91, expected 01 06 00 7D 00 FB 58 51 (they differ from byte 5)";
    QTest::newRow("bytes shorter") << R"({"name": "s", "send": "write 250", "expect": {"bytes": "01 06 00 7D"}})"
                                   << false
                                   << "answer is 01 06 00 7D 00 FA 99 91, expected 01 06 00 7D (8 bytes where 4 were expected)";
    QTest::newRow("field value pass") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.register_value@0x0079": 1050}}})"
                                      << true << "modbus.register_value@0x0079 = 1050";
    QTest::newRow("field value fail") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.register_value@0x0079": 1051}}})"
                                      << false << "modbus.register_value@0x0079 is 1050, expected 1051";
    QTest::newRow("field index pass") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.register_value[12]": 8000}}})"
                                      << true << "modbus.register_value[12] = 8000";
    QTest::newRow("field range pass") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.byte_count": {"min": 40, "max": 44}}}})"
                                      << true << "modbus.byte_count = 44";
    QTest::newRow("field range fail") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.register_value@0x0083": {"min": 0, "max": 79}}}})"
                                      << false << "modbus.register_value@0x0083 is 80, expected 0 to 79";
    QTest::newRow("field missing") << R"({"name": "s", "send": "read all", "expect": {"fields": {"modbus.exception_code": 2}}})"
                                   << false << "modbus.exception_code: no such field in the answer";
    QTest::newRow("exception pass") << R"({"name": "s", "send": "outside", "expect": {"exception": 2}})"
                                    << true << "exception 0x02 (Illegal Data Address), as expected";
    QTest::newRow("exception other code") << R"({"name": "s", "send": "outside", "expect": {"exception": "0x03"}})"
                                          << false
                                          << "expected exception 0x03 (Illegal Data Value), got an exception 0x02 (Illegal Data Address)";
    QTest::newRow("exception fail") << R"({"name": "s", "send": "read all", "expect": {"exception": 2}})"
                                    << false << "expected exception 0x02 (Illegal Data Address), got a normal answer";
    QTest::newRow("no answer pass") << R"({"name": "s", "send": "broadcast", "expect": {"noAnswer": true}})"
                                    << true << "no answer, as expected";
    QTest::newRow("no answer fail") << R"({"name": "s", "send": "write 250", "expect": {"noAnswer": true}})"
                                    << false << "expected no answer, got a normal answer: 01 06 00 7D 00 FA 99 91";
    QTest::newRow("plain send pass") << R"({"name": "s", "send": "read all"})" << true << "answered";
    QTest::newRow("plain send fail") << R"({"name": "s", "send": "outside"})" << false
                                     << "expected an answer, got an exception 0x02 (Illegal Data Address)";
    QTest::newRow("inline form") << R"({"name": "s", "send": {"function": 3, "unit": 3, "address": 121, "quantity": 2},
                                      "expect": {"fields": {"modbus.register_value@121": 1050, "modbus.register_value@122": 0}}})"
                                 << true << "modbus.register_value@121 = 1050";
    QTest::newRow("expect step pass") << R"({"name": "s", "send": "read all"}, {"name": "e", "expect": {"fields": {"modbus.register_value@0x007F": 1000}}})"
                                      << true << "modbus.register_value@0x007F = 1000";
    QTest::newRow("expect step fail") << R"({"name": "s", "send": "read all"}, {"name": "e", "expect": {"exception": 1}})"
                                      << false << "expected exception 0x01 (Illegal Function), got a normal answer";
}

void TestPlanRunner::expectations()
{
    QFETCH(QString, plan);
    QFETCH(bool, passes);
    QFETCH(QString, reason);
    const SessionDocument doc = document(kRequests, plan);
    PlanRunner runner(doc, m_sim.url(), SessionTarget{});
    int observed = 0;
    const PlanResult result = runner.run([&observed](const StepResult &) { ++observed; });
    QCOMPARE(observed, int(result.steps.size()));
    QVERIFY(!result.steps.isEmpty());
    const StepResult &last = result.steps.constLast();
    QVERIFY2(!last.reasons.isEmpty(), qPrintable(last.detail));
    QCOMPARE(last.reasons.constFirst(), reason);
    QCOMPARE(last.outcome, passes ? StepResult::Outcome::Passed : StepResult::Outcome::Failed);
    QCOMPARE(result.passed(), passes);
    QVERIFY(!result.linkFailed);
}

void TestPlanRunner::pollBounds_data()
{
    QTest::addColumn<QString>("bounds");
    QTest::addColumn<bool>("passes");
    QTest::addColumn<QStringList>("reasons");

    // No wall-clock bound is asserted: a latency below 1 ns cannot be, one below 60 s always is.
    QTest::newRow("counts hold") << R"("count == 20", "timeouts == 0", "error_rate == 0 %", "ok >= 20")" << true
                                 << QStringList{QStringLiteral("count == 20 (count is 20)"), QStringLiteral("timeouts == 0 (timeouts is 0)"),
                                                QStringLiteral("error_rate == 0 % (error_rate is 0.00 %)"), QStringLiteral("ok >= 20 (ok is 20)")};
    QTest::newRow("count fails") << R"("count == 19", "timeouts == 0")" << false
                                 << QStringList{QStringLiteral("count == 19 does not hold: count is 20")};
    QTest::newRow("latency below 1 ns fails") << R"("p95 < 1 ns", "max < 60 s")" << false << QStringList{};
    QTest::newRow("latency within a minute") << R"("p95 < 60 s", "median <= 60000 ms", "p99.9 < 60000000 us")" << true << QStringList{};
}

void TestPlanRunner::pollBounds()
{
    QFETCH(QString, bounds);
    QFETCH(bool, passes);
    QFETCH(QStringList, reasons);
    const SessionDocument doc = document(
        kRequests, QStringLiteral(R"({"name": "p", "poll": {"requests": ["read all"], "intervalMs": 0, "count": 20}, "expect": [%1]})").arg(bounds));
    PlanRunner runner(doc, m_sim.url(), SessionTarget{});
    const PlanResult result = runner.run();
    QCOMPARE(result.steps.size(), 1);
    const StepResult &step = result.steps.constFirst();
    QCOMPARE(step.outcome, passes ? StepResult::Outcome::Passed : StepResult::Outcome::Failed);
    QVERIFY2(step.detail.startsWith(QLatin1String("20 transactions, 20 ok, 0 failed, latency median ")), qPrintable(step.detail));
    if (!reasons.isEmpty())
        QCOMPARE(step.reasons, reasons);
    else if (!passes)
        QVERIFY2(step.reasons.constFirst().startsWith(QLatin1String("p95 < 1 ns does not hold: p95 is ")), qPrintable(step.reasons.join(u'\n')));
}

void TestPlanRunner::junitReport()
{
    const SessionDocument doc = document(kRequests, QStringLiteral(R"(
        {"name": "settings", "send": "read all", "expect": {"fields": {"modbus.register_value@0x0079": 1050}}},
        {"name": "wrong value", "send": "read all", "expect": {"fields": {"modbus.register_value@0x0079": 7}}},
        {"name": "twice", "repeat": 2, "steps": [{"name": "pause", "wait": 10}]})"));
    PlanRunner runner(doc, m_sim.url(), SessionTarget{});
    const PlanResult result = runner.run();
    QCOMPARE(result.steps.size(), 4);
    QVERIFY(!result.passed());

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("results.xml"));
    QString error;
    QVERIFY2(JUnitReport::write(result, path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const JUnitSuite suite = readJUnit(file.readAll());
    QVERIFY2(suite.error.isEmpty(), qPrintable(suite.error));
    QCOMPARE(suite.attributes.value(QStringLiteral("name")), QStringLiteral("plan test"));
    QCOMPARE(suite.attributes.value(QStringLiteral("tests")), QStringLiteral("4"));
    QCOMPARE(suite.attributes.value(QStringLiteral("failures")), QStringLiteral("1"));
    QCOMPARE(suite.attributes.value(QStringLiteral("errors")), QStringLiteral("0"));
    QCOMPARE(suite.attributes.value(QStringLiteral("skipped")), QStringLiteral("0"));
    QCOMPARE(suite.cases.size(), 4);
    QCOMPARE(suite.cases.at(0).name, QStringLiteral("settings"));
    QCOMPARE(suite.cases.at(0).element, QString());
    QCOMPARE(suite.cases.at(1).name, QStringLiteral("wrong value"));
    QCOMPARE(suite.cases.at(1).classname, QStringLiteral("plan test.plan[1]"));
    QCOMPARE(suite.cases.at(1).element, QStringLiteral("failure"));
    QCOMPARE(suite.cases.at(1).message, QStringLiteral("modbus.register_value@0x0079 is 1050, expected 7"));
    QCOMPARE(suite.cases.at(2).name, QStringLiteral("pause (1/2)"));
    QCOMPARE(suite.cases.at(3).name, QStringLiteral("pause (2/2)"));
    QCOMPARE(suite.cases.at(3).classname, QStringLiteral("plan test.plan[2].steps[0]"));
}

void TestPlanRunner::linkError()
{
    // A port nobody listens on: bound by the OS, then closed.
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const quint16 port = server.serverPort();
    server.close();
    LinkUrl url = m_sim.url();
    url.port = port;

    const SessionDocument doc = document(kRequests, QStringLiteral(R"(
        {"name": "first", "send": "read all"}, {"name": "second", "send": "read all"},
        {"name": "poll", "poll": {"requests": ["read all"], "count": 3}},
        {"name": "often", "repeat": 1000000, "steps": [{"name": "read", "send": "read all"}]})"));
    PlanRunner runner(doc, url, SessionTarget{});
    const PlanResult result = runner.run();
    QVERIFY(result.linkFailed);
    QVERIFY2(!result.linkMessage.isEmpty(), "a link error says what the link said");
    QCOMPARE(result.steps.size(), 4); // the repetitions left are one line, however many
    // ... that counts every run it stands for: the count is the planned one however the run ends.
    QCOMPARE(result.planned, 1000003);
    QCOMPARE(result.total(), 1000003);
    QCOMPARE(result.steps.at(3).runs, 1000000);
    QCOMPARE(result.count(StepResult::Outcome::Skipped), 1000002);
    QCOMPARE(result.steps.at(3).name, QStringLiteral("often (1/1000000 to 1000000/1000000)"));
    QCOMPARE(result.steps.at(3).outcome, StepResult::Outcome::Skipped);
    QCOMPARE(result.steps.at(0).outcome, StepResult::Outcome::Error);
    QCOMPARE(result.steps.at(1).outcome, StepResult::Outcome::Skipped);
    QCOMPARE(result.steps.at(2).outcome, StepResult::Outcome::Skipped);
    QCOMPARE(result.steps.at(1).path, QStringLiteral("plan[1]"));
    QCOMPARE(result.steps.at(2).path, QStringLiteral("plan[2]"));
    QCOMPARE(result.steps.at(0).detail, QStringLiteral("not sent (the link failed first): 01 03 00 79 00 16 15 DD"));

    const JUnitSuite suite = readJUnit(JUnitReport::toXml(result));
    QCOMPARE(suite.attributes.value(QStringLiteral("errors")), QStringLiteral("1"));
    QCOMPARE(suite.attributes.value(QStringLiteral("skipped")), QStringLiteral("1000002"));
    QCOMPARE(suite.attributes.value(QStringLiteral("tests")), QStringLiteral("1000003"));
    QCOMPARE(suite.cases.at(0).element, QStringLiteral("error"));
    QCOMPARE(suite.cases.at(0).message, result.linkMessage);
    QCOMPARE(suite.cases.at(2).element, QStringLiteral("skipped"));
}

void TestPlanRunner::interruptedWaitIsSkipped()
{
    // Stopped (Ctrl-C, the window's Stop) during a wait: the wait is cut short, not failed, and
    // every run left is reported skipped, so the count is the planned one.
    const SessionDocument doc = document(kRequests, QStringLiteral(R"(
        {"name": "first", "send": "read all"},
        {"name": "settle", "wait": "30 s"},
        {"name": "again", "repeat": 3, "steps": [{"name": "read", "send": "read all"}, {"name": "pause", "wait": 10}]})"));
    PlanRunner runner(doc, m_sim.url(), SessionTarget{});
    QTimer::singleShot(200, [&runner] { runner.stop(); });
    const PlanResult result = runner.run();
    QVERIFY(result.interrupted);
    QCOMPARE(result.planned, 8);
    QCOMPARE(result.total(), 8);
    QCOMPARE(result.steps.size(), 8);
    QCOMPARE(result.count(StepResult::Outcome::Failed), 0);
    QCOMPARE(result.count(StepResult::Outcome::Passed), 1);
    QCOMPARE(result.count(StepResult::Outcome::Skipped), 7);
    QCOMPARE(result.steps.at(1).name, QStringLiteral("settle"));
    QVERIFY2(result.steps.at(1).reasons.constFirst().startsWith(QLatin1String("interrupted after ")), qPrintable(result.steps.at(1).reasons.join(u';')));
    QCOMPARE(result.steps.constLast().name, QStringLiteral("pause (3/3)"));
    const JUnitSuite suite = readJUnit(JUnitReport::toXml(result));
    QCOMPARE(suite.attributes.value(QStringLiteral("tests")), QStringLiteral("8"));
    QCOMPARE(suite.attributes.value(QStringLiteral("failures")), QStringLiteral("0"));
    QCOMPARE(suite.attributes.value(QStringLiteral("skipped")), QStringLiteral("7"));
    QCOMPARE(suite.cases.size(), 8);
}

void TestPlanRunner::shippedExample()
{
    // docs/examples/rosrao-gamma.mbscope.json passes against the profile it was written for.
    const QString path = sessiontest::sourceDir() + QStringLiteral("/docs/examples/rosrao-gamma.mbscope.json");
    const SessionLoadResult loaded = SessionReader::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    // Its latency bound is wall-clock time, which a loaded test machine may not keep: the bounds
    // of the poll step are replaced by counts (the bounds themselves are tested above).
    SessionDocument doc = *loaded.document;
    QCOMPARE(doc.plan.at(9).kind, PlanStep::Kind::Poll);
    QCOMPARE(doc.plan.at(9).bounds.constFirst().text, QStringLiteral("p95 < 20 ms"));
    doc.plan[9].bounds = {*PollBound::parse(u"count == 50").bound, *PollBound::parse(u"timeouts == 0").bound};
    PlanRunner runner(doc, m_sim.url(), doc.target);
    const PlanResult result = runner.run();
    QStringList failures;
    for (const StepResult &s : result.steps) {
        if (s.outcome != StepResult::Outcome::Passed)
            failures.append(QStringLiteral("%1 %2: %3 (%4)").arg(s.path, s.name, s.reasons.join(QStringLiteral("; ")), s.detail));
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(u'\n')));
    QCOMPARE(result.steps.size(), 16); // 10 steps, then 2 steps 3 times
    QVERIFY(result.passed());
}

QTEST_GUILESS_MAIN(TestPlanRunner)
#include "tst_planrunner.moc"
