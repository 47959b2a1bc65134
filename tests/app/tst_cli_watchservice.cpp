// `mbscope watch` as a service, against the real peers it serves (issue 17): Debian's prometheus
// scraping it while it polls `mbscope simulate` (a register's value and the link's health queried
// through Prometheus's HTTP API; the simulator stopped, then restarted, shows in the series and
// the service carries on), promtool checking the live exposition, and mosquitto with
// mosquitto_sub (messages per poll, the retained status, the last will when watch is killed,
// writes from /set refused without --mqtt-writes and reaching the simulator with it). Also SIGHUP
// (the session read again), SIGTERM (a clean stop) and refused options. Every peer runs on a free
// loopback port with a configuration the test writes, and is stopped by the test.
#include "clitest.h"
#include "servicepeers.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtCore/QStandardPaths>
#include <QtCore/QFileInfo>
#include <QtTest/QtTest>

#include <csignal>

using namespace mbscope::testcli;

namespace {

// conformance profile, unit 1: holding register a holds 1000 + 3a.
QByteArray sessionJson(const QString &target, bool second = false)
{
    QByteArray json = R"({"format": "mbscope-session", "version": 2, "name": "service test",
  "watches": [
    {"name": "plant", "target": "TARGET", "unit": 1, "function": 3, "address": 0, "quantity": 4, "intervalMs": 200,
     "points": [{"address": 0, "name": "pressure", "unit": "hPa", "scale": 0.1},
                {"address": 1, "name": "setpoint", "unit": "degC", "writable": true},
                {"address": 2, "name": "fixed"}]})";
    if (second)
        json += R"(,
    {"name": "second", "target": "TARGET", "unit": 1, "function": 4, "address": 10, "quantity": 2, "intervalMs": 300})";
    json += R"(
  ],
  "watchLinks": [{"target": "TARGET", "timeoutMs": 300, "reconnectMinMs": 200, "reconnectMaxMs": 1000}]
})";
    json.replace("TARGET", target.toUtf8());
    return json;
}

QString metricsUrlOf(ChildProcess &watch)
{
    if (!watch.waitForOutput("metrics at http://", 30000))
        return {};
    watch.waitForOutput("/metrics\n", 2000);
    static const QRegularExpression url(QStringLiteral(R"((http://\S+/metrics))"));
    return url.match(QString::fromUtf8(watch.output())).captured(1);
}

// `mbscope read` of one holding register of the simulator.
int readRegister(const QString &target, int address)
{
    const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--address"),
                                    QString::number(address), QStringLiteral("--json")});
    const QJsonArray values = r.json().value(QStringLiteral("values")).toArray();
    return values.isEmpty() ? -1 : values.first().toObject().value(QStringLiteral("raw")).toInt();
}

} // namespace

class TestCliWatchService : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void metricsEndpoint();
    void prometheusScrapesAndSeesTheOutage();
    void mqttMessagesStatusAndLastWill();
    void mqttBrokerThatComesLater();
    void mqttWritesRefusedWithoutTheOption();
    void mqttWritesReachTheSimulator();
    void hangupReloadsTermStopsCleanly();
    void ruleActiveGauge();
    void guideExamples();
    void refusedOptions_data();
    void refusedOptions();
    void credentialsFileChecked();

private:
    QString writeSession(const QString &target, bool second = false);
    bool startWatch(ChildProcess &watch, const QStringList &extra);

    std::unique_ptr<QTemporaryDir> m_dir;
    Simulator m_simulator;
    QString m_session;
};

void TestCliWatchService::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QString error;
    QVERIFY2(m_simulator.start(QStringLiteral("conformance"), 0, &error), qPrintable(error));
    m_session = writeSession(m_simulator.url());
}

void TestCliWatchService::cleanup()
{
    m_simulator.stop();
}

QString TestCliWatchService::writeSession(const QString &target, bool second)
{
    const QString path = m_dir->filePath(QStringLiteral("bench.mbscope.json"));
    QFile f(path);
    if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        f.write(sessionJson(target, second));
    return path;
}

bool TestCliWatchService::startWatch(ChildProcess &watch, const QStringList &extra)
{
    QString error;
    if (!watch.start(mbscopePath(), QStringList{QStringLiteral("watch"), m_session} + extra, &error)) {
        qWarning("%s", qPrintable(error));
        return false;
    }
    return true;
}

void TestCliWatchService::metricsEndpoint()
{
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0")}));
    const QString url = metricsUrlOf(watch);
    QVERIFY2(!url.isEmpty(), watch.output().constData());
    QVERIFY2(url.startsWith(QLatin1String("http://127.0.0.1:")), qPrintable(url));

    // The first polls: the value of pressure (1000 x 0.1 hPa), the link up, polls counted.
    HttpReply reply;
    QTRY_VERIFY_WITH_TIMEOUT((reply = httpGet(url), metricValue(reply.body, QStringLiteral("mbscope_watch_polls_total")).value_or(0) >= 3),
                             20000);
    QCOMPARE(reply.status, 200);
    QVERIFY2(reply.contentType.startsWith("text/plain; version=0.0.4"), reply.contentType);
    const QMap<QString, QString> pressure{{QStringLiteral("watch"), QStringLiteral("plant")}, {QStringLiteral("name"), QStringLiteral("pressure")},
                                          {QStringLiteral("engineering_unit"), QStringLiteral("hPa")}, {QStringLiteral("address"), QStringLiteral("0")},
                                          {QStringLiteral("table"), QStringLiteral("holding_registers")}, {QStringLiteral("unit"), QStringLiteral("1")},
                                          {QStringLiteral("target"), m_simulator.url()}};
    QCOMPARE(metricValue(reply.body, QStringLiteral("mbscope_watch_value"), pressure).value_or(-1), 100.0);
    QCOMPARE(metricValue(reply.body, QStringLiteral("mbscope_watch_value"), {{QStringLiteral("address"), QStringLiteral("3")}}).value_or(-1), 1009.0);
    QCOMPARE(metricValue(reply.body, QStringLiteral("mbscope_link_up")).value_or(-1), 1.0);
    QCOMPARE(metricValue(reply.body, QStringLiteral("mbscope_watch_up")).value_or(-1), 1.0);
    QVERIFY(metricValue(reply.body, QStringLiteral("mbscope_watch_latency_seconds_count")).value_or(0) >= 3);
    QVERIFY(metricValue(reply.body, QStringLiteral("mbscope_watch_last_success_timestamp_seconds")).value_or(0) >
            double(QDateTime::currentSecsSinceEpoch() - 60));
    QVERIFY(metricValue(reply.body, QStringLiteral("process_resident_memory_bytes")).value_or(0) > 0);

    // Prometheus's linter over the live exposition.
    QString why;
    if (haveProgram(QStringLiteral("promtool"), QStringLiteral("prometheus"), &why)) {
        QProcess promtool;
        promtool.setProcessChannelMode(QProcess::MergedChannels);
        promtool.start(programPath(QStringLiteral("promtool")), {QStringLiteral("check"), QStringLiteral("metrics")});
        QVERIFY(promtool.waitForStarted());
        promtool.write(reply.body);
        promtool.closeWriteChannel();
        QVERIFY(promtool.waitForFinished(30000));
        const QByteArray lint = promtool.readAll();
        QVERIFY2(promtool.exitCode() == 0 && lint.trimmed().isEmpty(), lint + "\n---\n" + reply.body);
    } else {
        qWarning("%s", qPrintable(why));
    }

    // OpenMetrics when asked, as Prometheus asks; 404 elsewhere.
    const HttpReply open = httpGet(url, "application/openmetrics-text;version=1.0.0,text/plain;version=0.0.4;q=0.5");
    QVERIFY2(open.contentType.startsWith("application/openmetrics-text; version=1.0.0"), open.contentType);
    QVERIFY(open.body.endsWith("# EOF\n"));
    QVERIFY(open.body.contains("# TYPE mbscope_watch_polls counter\n"));
    QCOMPARE(httpGet(QString(url).replace(QLatin1String("/metrics"), QLatin1String("/nothing"))).status, 404);
    QCOMPARE(watch.stop(SIGTERM), 0);
}

void TestCliWatchService::prometheusScrapesAndSeesTheOutage()
{
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0")}));
    const QString url = metricsUrlOf(watch);
    QVERIFY2(!url.isEmpty(), watch.output().constData());
    const QString hostPort = QUrl(url).host() + QLatin1Char(':') + QString::number(QUrl(url).port());

    Prometheus prometheus;
    QString error;
    if (!prometheus.start({hostPort}, QStringLiteral("1s"), &error)) {
        if (error.contains(QLatin1String("not installed")))
            QSKIP(qPrintable(error));
        QFAIL(qPrintable(error));
    }
    double last = -1;
    const QString pressure = QStringLiteral(R"(mbscope_watch_value{job="mbscope",watch="plant",name="pressure"})");
    QVERIFY2(prometheus.waitFor(pressure, [](double v) { return v == 100; }, 60000, &last),
             qPrintable(QStringLiteral("pressure %1; prometheus: %2").arg(last).arg(QString::fromUtf8(prometheus.output()))));
    QVERIFY(prometheus.waitFor(QStringLiteral(R"(up{job="mbscope"})"), [](double v) { return v == 1; }, 30000));
    QVERIFY(prometheus.waitFor(QStringLiteral("mbscope_link_up"), [](double v) { return v == 1; }, 30000));

    // The device goes away: the watch is down, its values absent, the link down and retried.
    const quint16 port = m_simulator.port();
    m_simulator.stop();
    QVERIFY2(prometheus.waitFor(QStringLiteral("mbscope_watch_up"), [](double v) { return v == 0; }, 30000, &last),
             qPrintable(QString::number(last)));
    QVERIFY(prometheus.waitFor(QStringLiteral("mbscope_link_up"), [](double v) { return v == 0; }, 30000));
    QVERIFY(prometheus.waitFor(QStringLiteral("count(mbscope_watch_value) or vector(0)"), [](double v) { return v == 0; }, 30000));
    QVERIFY(prometheus.waitFor(QStringLiteral("mbscope_link_failures_total"), [](double v) { return v >= 1; }, 30000));

    // It comes back on the same port: the service carried on and polls again.
    QVERIFY2(m_simulator.start(QStringLiteral("conformance"), port, &error), qPrintable(error));
    QVERIFY2(prometheus.waitFor(QStringLiteral("mbscope_watch_up"), [](double v) { return v == 1; }, 60000, &last),
             qPrintable(QString::number(last)));
    QVERIFY(prometheus.waitFor(pressure, [](double v) { return v == 100; }, 30000));
    QVERIFY(prometheus.waitFor(QStringLiteral("mbscope_link_reconnects_total"), [](double v) { return v >= 1; }, 30000));
    // The series holds the outage; the scrape target never went down.
    QVERIFY(prometheus.waitFor(QStringLiteral("min_over_time(mbscope_watch_up[5m])"), [](double v) { return v == 0; }, 5000));
    QVERIFY(prometheus.waitFor(QStringLiteral(R"(min_over_time(up{job="mbscope"}[5m]))"), [](double v) { return v == 1; }, 5000));
    QVERIFY(prometheus.waitFor(QStringLiteral("rate(mbscope_watch_polls_total[1m]) > 0"), [](double v) { return v > 0; }, 10000));
    QVERIFY(watch.isRunning());
    QCOMPARE(watch.stop(SIGTERM), 1); // stopped cleanly; 1: some polls failed
    const QByteArray log = watch.output();
    QVERIFY2(log.contains("warning: link ") && log.contains(": down"), log.constData());
    QVERIFY2(log.contains("notice: link ") && log.contains("up again"), log.constData());
}

void TestCliWatchService::mqttMessagesStatusAndLastWill()
{
    Mosquitto broker;
    QString error;
    if (!broker.start(&error)) {
        if (error.contains(QLatin1String("not installed")))
            QSKIP(qPrintable(error));
        QFAIL(qPrintable(error));
    }
    Subscriber all;
    QVERIFY2(all.start(broker.port(), QStringLiteral("svc/#"), &error), qPrintable(error));
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--mqtt"), broker.url(QStringLiteral("svc/lab"))}));

    QVERIFY2(all.waitFor(QStringLiteral("svc/lab/status"), "online", 20000), watch.output().constData());
    const std::optional<Subscriber::Message> poll = all.waitFor(QStringLiteral("svc/lab/plant"), "\"status\":\"ok\"", 20000);
    QVERIFY2(poll, watch.output().constData());
    const QJsonObject message = QJsonDocument::fromJson(poll->payload).object();
    QCOMPARE(message.value(QStringLiteral("watch")).toString(), QStringLiteral("plant"));
    QCOMPARE(message.value(QStringLiteral("values")).toObject().value(QStringLiteral("pressure")).toDouble(), 100.0);
    QCOMPARE(message.value(QStringLiteral("values")).toObject().value(QStringLiteral("setpoint")).toDouble(), 1003.0);
    QCOMPARE(message.value(QStringLiteral("values")).toObject().value(QStringLiteral("0x0003")).toDouble(), 1009.0);
    QCOMPARE(message.value(QStringLiteral("units")).toObject().value(QStringLiteral("pressure")).toString(), QStringLiteral("hPa"));
    QVERIFY(message.value(QStringLiteral("latency_seconds")).toDouble() > 0);
    // A message per poll (200 ms): several within a couple of seconds.
    QTRY_VERIFY_WITH_TIMEOUT(std::count_if(all.messages().cbegin(), all.messages().cend(),
                                           [](const Subscriber::Message &m) { return m.topic == QLatin1String("svc/lab/plant"); }) >= 5,
                             10000);

    // The status is retained: a subscriber that comes later gets it at once, marked retained.
    Subscriber late;
    QVERIFY2(late.start(broker.port(), QStringLiteral("svc/lab/status"), &error), qPrintable(error));
    const std::optional<Subscriber::Message> status = late.waitFor(QStringLiteral("svc/lab/status"), "online", 10000);
    QVERIFY(status);
    QVERIFY(status->retained);

    // Killed without a goodbye: the broker publishes the last will.
    watch.stop(SIGKILL);
    QVERIFY2(all.waitFor(QStringLiteral("svc/lab/status"), "offline", 30000), broker.output().constData());
    Subscriber after;
    QVERIFY2(after.start(broker.port(), QStringLiteral("svc/lab/status"), &error), qPrintable(error));
    const std::optional<Subscriber::Message> will = after.waitFor(QStringLiteral("svc/lab/status"), "offline", 10000);
    QVERIFY(will && will->retained);
}

// A broker that is not there when watch starts: watch says so and tries again until it is, then
// publishes (libmosquitto's own thread never retries a first connection that failed).
void TestCliWatchService::mqttBrokerThatComesLater()
{
    if (QStandardPaths::findExecutable(QStringLiteral("mosquitto")).isEmpty()
        && !QFileInfo::exists(QStringLiteral("/usr/sbin/mosquitto")))
        QSKIP("mosquitto is not installed (scripts/install-deps.sh --tests installs it)");
    const quint16 port = closedPort();
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--mqtt"), QStringLiteral("mqtt://127.0.0.1:%1/later").arg(port)}));
    QVERIFY2(watch.waitForOutput("cannot reach", 10000), watch.output().constData());
    Mosquitto broker;
    QString error;
    QVERIFY2(broker.start(&error, port), qPrintable(error));
    Subscriber status;
    QVERIFY2(status.start(port, QStringLiteral("later/status"), &error), qPrintable(error));
    QVERIFY2(status.waitFor(QStringLiteral("later/status"), "online", 20000), watch.output().constData());
    QVERIFY2(watch.waitForOutput("MQTT: connected to", 10000), watch.output().constData());
}

void TestCliWatchService::mqttWritesRefusedWithoutTheOption()
{
    Mosquitto broker;
    QString error;
    if (!broker.start(&error)) {
        if (error.contains(QLatin1String("not installed")))
            QSKIP(qPrintable(error));
        QFAIL(qPrintable(error));
    }
    Subscriber all;
    QVERIFY2(all.start(broker.port(), QStringLiteral("svc/#"), &error), qPrintable(error));
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--mqtt"), broker.url(QStringLiteral("svc/lab"))}));
    QVERIFY2(all.waitFor(QStringLiteral("svc/lab/plant"), "\"setpoint\":1003", 20000), watch.output().constData());
    QVERIFY(publish(broker.port(), QStringLiteral("svc/lab/plant/set"), R"({"setpoint": 4321})", &error));
    // Polls go on; the device keeps its value, and nothing answered the /set.
    QTest::qWait(1500);
    QVERIFY(all.waitFor(QStringLiteral("svc/lab/plant"), "\"setpoint\":1003", 5000));
    QCOMPARE(readRegister(m_simulator.url(), 1), 1003);
    for (const Subscriber::Message &m : all.messages())
        QVERIFY2(m.topic != QLatin1String("svc/lab/plant/set/result"), m.payload.constData());
    QVERIFY2(!watch.output().contains("writing"), watch.output().constData());
    QCOMPARE(watch.stop(SIGTERM), 0);
}

void TestCliWatchService::mqttWritesReachTheSimulator()
{
    Mosquitto broker;
    QString error;
    if (!broker.start(&error)) {
        if (error.contains(QLatin1String("not installed")))
            QSKIP(qPrintable(error));
        QFAIL(qPrintable(error));
    }
    Subscriber all;
    QVERIFY2(all.start(broker.port(), QStringLiteral("svc/#"), &error), qPrintable(error));
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--mqtt"), broker.url(QStringLiteral("svc/lab")), QStringLiteral("--mqtt-writes")}));
    QVERIFY2(all.waitFor(QStringLiteral("svc/lab/status"), "online", 20000), watch.output().constData());
    QTest::qWait(300); // subscribed to /set once connected

    // A point not marked writable: refused, said on set/result, the device untouched.
    QVERIFY(publish(broker.port(), QStringLiteral("svc/lab/plant/set"), R"({"fixed": 5})", &error));
    const std::optional<Subscriber::Message> refused = all.waitFor(QStringLiteral("svc/lab/plant/set/result"), "\"ok\":false", 10000);
    QVERIFY2(refused, watch.output().constData());
    QVERIFY2(refused->payload.contains("not marked writable"), refused->payload.constData());
    QCOMPARE(readRegister(m_simulator.url(), 2), 1006);

    // The writable one: written, read back by the next polls and by mbscope read.
    QVERIFY(publish(broker.port(), QStringLiteral("svc/lab/plant/set"), R"({"setpoint": 4321})", &error));
    const std::optional<Subscriber::Message> written = all.waitFor(QStringLiteral("svc/lab/plant/set/result"), "\"ok\":true", 10000);
    QVERIFY2(written, watch.output().constData());
    QVERIFY(all.waitFor(QStringLiteral("svc/lab/plant"), "\"setpoint\":4321", 10000));
    QCOMPARE(readRegister(m_simulator.url(), 1), 4321);
    QCOMPARE(watch.stop(SIGTERM), 0);
    // A clean stop says goodbye itself.
    QVERIFY(all.waitFor(QStringLiteral("svc/lab/status"), "offline", 10000));
}

void TestCliWatchService::hangupReloadsTermStopsCleanly()
{
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0")}));
    const QString url = metricsUrlOf(watch);
    QVERIFY2(!url.isEmpty(), watch.output().constData());
    QTRY_VERIFY_WITH_TIMEOUT(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_up"), {{QStringLiteral("watch"), QStringLiteral("plant")}}) == 1.0,
                             20000);
    QVERIFY(!metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_polls_total"), {{QStringLiteral("watch"), QStringLiteral("second")}}));

    // A second watch in the session; SIGHUP reads it again.
    writeSession(m_simulator.url(), true);
    watch.signal(SIGHUP);
    QTRY_VERIFY_WITH_TIMEOUT(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_up"), {{QStringLiteral("watch"), QStringLiteral("second")}}) == 1.0,
                             20000);
    QCOMPARE(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_value"),
                         {{QStringLiteral("watch"), QStringLiteral("second")}, {QStringLiteral("address"), QStringLiteral("10")}})
                 .value_or(-1),
             40020.0);

    // A session that no longer reads: said, and the running watches stay.
    QFile broken(m_session);
    QVERIFY(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
    broken.write("{ not json");
    broken.close();
    watch.signal(SIGHUP);
    QVERIFY2(watch.waitForOutput("error:", 10000), watch.output().constData());
    QVERIFY(watch.isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_up"), {{QStringLiteral("watch"), QStringLiteral("second")}}) == 1.0,
                             10000);

    QCOMPARE(watch.stop(SIGTERM), 0);
}

// mbscope_watch_rule_active against the simulator: a rule that holds reads 1 (with the rule, its
// point and severity as labels), and 0 once it cleared, the register written past it with
// mbscope write while the service polls; the rule's firings are counted beside it.
void TestCliWatchService::ruleActiveGauge()
{
    QByteArray json = R"({"format": "mbscope-session", "version": 2, "name": "rules",
  "watches": [{"name": "plant", "target": "TARGET", "unit": 1, "function": 3, "address": 0, "quantity": 4, "intervalMs": 100,
               "points": [{"address": 1, "name": "setpoint", "writable": true}],
               "rules": [{"point": "setpoint", "below": 2000, "severity": "alarm", "message": "setpoint low"}]}]})";
    json.replace("TARGET", m_simulator.url().toUtf8());
    QFile f(m_session);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(json);
    f.close();
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0")}));
    const QString url = metricsUrlOf(watch);
    QVERIFY2(!url.isEmpty(), watch.output().constData());
    const QMap<QString, QString> setpointRule{{QStringLiteral("watch"), QStringLiteral("plant")}, {QStringLiteral("rule"), QStringLiteral("0")},
                                              {QStringLiteral("point"), QStringLiteral("setpoint")}, {QStringLiteral("severity"), QStringLiteral("alarm")}};
    // 1003 < 2000: the rule holds from the first poll.
    QTRY_VERIFY_WITH_TIMEOUT(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_rule_active"), setpointRule) == 1.0, 20000);
    QCOMPARE(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_rule_firings_total")).value_or(-1), 1.0);
    QVERIFY2(watch.waitForOutput("error: watch 'plant': setpoint low fired (setpoint = 1003)", 10000), watch.output().constData());

    const CliResult w = runMbscope({QStringLiteral("write"), QStringLiteral("--target"), m_simulator.url(), QStringLiteral("--address"),
                                    QStringLiteral("1"), QStringLiteral("--registers"), QStringLiteral("2500"), QStringLiteral("--single")});
    QVERIFY2(w.exitCode == 0, w.describe().constData());
    QTRY_VERIFY_WITH_TIMEOUT(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_rule_active"), setpointRule) == 0.0, 20000);
    QVERIFY2(watch.waitForOutput("info: watch 'plant': setpoint low cleared (setpoint = 2500)", 10000), watch.output().constData());
    QCOMPARE(metricValue(httpGet(url).body, QStringLiteral("mbscope_watch_rule_firings_total")).value_or(-1), 1.0);
    QCOMPARE(watch.stop(SIGTERM), 0);
}

// docs/guide/fleet.md as written: its example session (the simulator's port put in), its PromQL
// queries run by a real Prometheus scraping watch, its MQTT subscriber and write.
void TestCliWatchService::guideExamples()
{
    const QString source = QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../..");
    QFile guide(source + QStringLiteral("/docs/guide/fleet.md"));
    QVERIFY(guide.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(guide.readAll());
    const qsizetype start = text.indexOf(QLatin1String("```promql\n"));
    QVERIFY(start >= 0);
    const qsizetype end = text.indexOf(QLatin1String("```"), start + 10);
    QStringList queries;
    for (const QString &line : text.mid(start + 10, end - start - 10).split(QLatin1Char('\n'))) {
        if (!line.trimmed().isEmpty() && !line.trimmed().startsWith(QLatin1Char('#')))
            queries.append(line.trimmed());
    }
    QVERIFY2(queries.size() >= 6, qPrintable(queries.join(QLatin1Char('\n'))));

    QFile example(source + QStringLiteral("/docs/examples/fleet-bench.mbscope.json"));
    QVERIFY(example.open(QIODevice::ReadOnly));
    QByteArray session = example.readAll();
    QVERIFY(session.contains("tcp://127.0.0.1:5020"));
    session.replace("tcp://127.0.0.1:5020", m_simulator.url().toUtf8());
    session.replace("\"$schema\": \"../session.schema.json\",", "");
    m_session = m_dir->filePath(QStringLiteral("fleet-bench.mbscope.json"));
    QFile copy(m_session);
    QVERIFY(copy.open(QIODevice::WriteOnly));
    copy.write(session);
    copy.close();

    Mosquitto broker;
    QString error;
    if (!broker.start(&error))
        QSKIP(qPrintable(error));
    Subscriber sub;
    QVERIFY2(sub.start(broker.port(), QStringLiteral("lab/#"), &error), qPrintable(error));
    ChildProcess watch;
    QVERIFY(startWatch(watch, {QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0"), QStringLiteral("--mqtt"),
                               QStringLiteral("mqtt://127.0.0.1:%1/lab/bench1").arg(broker.port()), QStringLiteral("--mqtt-writes")}));
    const QString url = metricsUrlOf(watch);
    QVERIFY2(!url.isEmpty(), watch.output().constData());
    Prometheus prometheus;
    if (!prometheus.start({QUrl(url).host() + QLatin1Char(':') + QString::number(QUrl(url).port())}, QStringLiteral("1s"), &error))
        QSKIP(qPrintable(error));

    // The subscriber's lines, and the write.
    QVERIFY2(sub.waitFor(QStringLiteral("lab/bench1/status"), "online", 20000), watch.output().constData());
    QVERIFY(sub.waitFor(QStringLiteral("lab/bench1/boiler"), "\"pressure\":100", 20000));
    QVERIFY(sub.waitFor(QStringLiteral("lab/bench1/inputs"), "\"0x0007\":40014", 20000));
    QVERIFY(sub.waitFor(QStringLiteral("lab/bench1/boiler/event"), "pressure above 95 kPa", 20000));
    QVERIFY(publish(broker.port(), QStringLiteral("lab/bench1/boiler/set"), R"({"setpoint": 65})", &error));
    QVERIFY(sub.waitFor(QStringLiteral("lab/bench1/boiler/set/result"), R"({"message":"written","ok":true,"point":"setpoint"})", 10000));
    QVERIFY(sub.waitFor(QStringLiteral("lab/bench1/boiler"), "\"setpoint\":65", 10000));

    // Every query of the guide is valid PromQL with an answer (but the two that look for trouble).
    QVERIFY(prometheus.waitFor(QStringLiteral("count(mbscope_watch_latency_seconds_count) and count(rate(mbscope_watch_polls_total[5m]))"),
                               [](double v) { return v >= 2; }, 60000));
    for (const QString &query : std::as_const(queries)) {
        const bool troubleOnly = query.contains(QLatin1String("last_success")) || query.contains(QLatin1String("exceptions_total"));
        QString why;
        QJsonObject data;
        QTRY_VERIFY2_WITH_TIMEOUT((data = prometheus.query(query, &why), !data.isEmpty() &&
                                   (troubleOnly || !data.value(QStringLiteral("result")).toArray().isEmpty())),
                                  qPrintable(query + QStringLiteral(": ") + why), 20000);
    }
    QCOMPARE(prometheus.scalar(QStringLiteral(R"(mbscope_watch_value{watch="boiler", name="pressure"})")).value_or(-1), 100.0);
    QCOMPARE(watch.stop(SIGTERM), 0);
}

void TestCliWatchService::refusedOptions_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("password in the URL") << QStringList{QStringLiteral("--mqtt"), QStringLiteral("mqtt://user:secret@127.0.0.1/x")}
                                         << QStringLiteral("--mqtt-credentials");
    QTest::newRow("not mqtt") << QStringList{QStringLiteral("--mqtt"), QStringLiteral("http://127.0.0.1/x")} << QStringLiteral("mqtt://");
    QTest::newRow("wildcard prefix") << QStringList{QStringLiteral("--mqtt"), QStringLiteral("mqtt://127.0.0.1/a/#")} << QStringLiteral("wildcards");
    QTest::newRow("writes without mqtt") << QStringList{QStringLiteral("--mqtt-writes")} << QStringLiteral("need --mqtt");
    QTest::newRow("metrics port") << QStringList{QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:http")} << QStringLiteral("port");
    QTest::newRow("metrics host") << QStringList{QStringLiteral("--metrics"), QStringLiteral("example.org:9464")} << QStringLiteral("IP address");
    QTest::newRow("log level") << QStringList{QStringLiteral("--log-level"), QStringLiteral("loud")} << QStringLiteral("--log-level");
    QTest::newRow("missing credentials") << QStringList{QStringLiteral("--mqtt"), QStringLiteral("mqtt://127.0.0.1/x"), QStringLiteral("--mqtt-credentials"),
                                                        QStringLiteral("/nonexistent/credentials")}
                                         << QStringLiteral("/nonexistent/credentials");
}

void TestCliWatchService::refusedOptions()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliResult r = runMbscope(QStringList{QStringLiteral("watch"), m_session} + arguments, 30000);
    QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(message), r.describe().constData());
    QVERIFY2(!r.errText().contains(QLatin1String("secret")), r.describe().constData());
}

// --mqtt-credentials: a file with a line after the password is refused, naming the line; one the
// group or others may read, and one without a password, are warned about (levelled, at start)
// and the service runs. Before, all three went by silently. No broker is needed: the warnings
// come first, and a broker not there is tried again while the polls go on.
void TestCliWatchService::credentialsFileChecked()
{
    // No broker listens there: a run whose credentials were read ends with exit 3 (the broker never
    // reached, issue 26 item 10), a file refused ends with exit 2 before any connection.
    const QString url = QStringLiteral("mqtt://127.0.0.1:%1/x").arg(closedPort());
    const auto writeCredentials = [this](const QString &name, const QByteArray &text, QFileDevice::Permissions permissions) {
        const QString path = m_dir->filePath(name);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(text);
        f.close();
        f.setPermissions(permissions);
        return path;
    };
    const QFileDevice::Permissions owner = QFileDevice::ReadOwner | QFileDevice::WriteOwner;

    const QString extra = writeCredentials(QStringLiteral("extra.txt"), "user\nsecret\nmore\n", owner);
    CliResult r = runMbscope({QStringLiteral("watch"), m_session, QStringLiteral("--mqtt"), url, QStringLiteral("--mqtt-credentials"), extra}, 30000);
    QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral("--mqtt-credentials: %1, line 3: unexpected").arg(extra)), r.describe().constData());
    QVERIFY2(!r.errText().contains(QLatin1String("secret")), r.describe().constData());

    const QString open = writeCredentials(QStringLiteral("open.txt"), "user\nsecret\n", owner | QFileDevice::ReadGroup | QFileDevice::ReadOther);
    r = runMbscope({QStringLiteral("watch"), m_session, QStringLiteral("--mqtt"), url, QStringLiteral("--mqtt-credentials"), open,
                    QStringLiteral("--duration"), QStringLiteral("300ms"), QStringLiteral("--quiet")}, 30000);
    QVERIFY2(r.finished && r.exitCode == 3, r.describe().constData()); // read, then the broker unreachable
    QVERIFY2(r.errText().contains(QStringLiteral(" warning: --mqtt-credentials: %1 may be read by every user: it holds the MQTT password; chmod 600 %1").arg(open)),
             r.describe().constData());
    QVERIFY2(!r.errText().contains(QLatin1String("secret")), r.describe().constData());

    const QString group = writeCredentials(QStringLiteral("group.txt"), "user\n", owner | QFileDevice::ReadGroup);
    r = runMbscope({QStringLiteral("watch"), m_session, QStringLiteral("--mqtt"), url, QStringLiteral("--mqtt-credentials"), group,
                    QStringLiteral("--duration"), QStringLiteral("300ms"), QStringLiteral("--quiet")}, 30000);
    QVERIFY2(r.finished && r.exitCode == 3, r.describe().constData()); // read, then the broker unreachable
    QVERIFY2(r.errText().contains(QStringLiteral("%1 may be read by its group").arg(group)), r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral(" warning: --mqtt-credentials: %1, line 2: no password: the broker gets the user name 'user' alone").arg(group)),
             r.describe().constData());

    const QString good = writeCredentials(QStringLiteral("good.txt"), "user\nsecret\n", owner);
    r = runMbscope({QStringLiteral("watch"), m_session, QStringLiteral("--mqtt"), url, QStringLiteral("--mqtt-credentials"), good,
                    QStringLiteral("--duration"), QStringLiteral("300ms"), QStringLiteral("--quiet")}, 30000);
    QVERIFY2(r.finished && r.exitCode == 3, r.describe().constData()); // read, then the broker unreachable
    QVERIFY2(!r.errText().contains(QLatin1String("--mqtt-credentials")), r.describe().constData());
}

QTEST_GUILESS_MAIN(TestCliWatchService)
#include "tst_cli_watchservice.moc"
