// `mbscope watch` end to end, the real binary against three simulated devices on three links at
// once (issue 16): rosrao-gamma over RTU-over-TCP, m221-plc over Modbus TCP, arduino-rs485 over a
// socat pty pair at 9600 baud. Values named and scaled, counters, a rule firing, the PLC killed
// while the others go on, its reconnect counted when it comes back, CSV files per watch; and a
// broken session refused with located messages.

#include "clitest.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <functional>

using namespace mbscope::testcli;

namespace {

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// `mbscope watch ... --json` running in the background, its JSON lines read as they come.
class WatchProcess
{
public:
    bool start(const QStringList &arguments)
    {
        m_process.start(mbscopePath(), arguments);
        return m_process.waitForStarted(30000);
    }
    // Reads lines until pred holds for the lines so far (or waitMs passes).
    bool waitFor(const std::function<bool(const QList<QJsonObject> &)> &pred, int waitMs = 30000)
    {
        QElapsedTimer timer;
        timer.start();
        while (!pred(m_lines)) {
            if (timer.elapsed() > waitMs || m_process.state() == QProcess::NotRunning)
                return false;
            m_process.waitForReadyRead(100);
            readLines();
        }
        return true;
    }
    int stop(int signal)
    {
        ::kill(pid_t(m_process.processId()), signal);
        if (!m_process.waitForFinished(20000))
            m_process.kill();
        readLines();
        m_err += m_process.readAllStandardError();
        return m_process.exitStatus() == QProcess::NormalExit ? m_process.exitCode() : -1;
    }
    [[nodiscard]] const QList<QJsonObject> &lines() const { return m_lines; }
    [[nodiscard]] QByteArray err() const { return m_err; }

private:
    void readLines()
    {
        m_buffer += m_process.readAllStandardOutput();
        qsizetype end;
        while ((end = m_buffer.indexOf('\n')) >= 0) {
            m_lines.append(QJsonDocument::fromJson(m_buffer.left(end)).object());
            m_buffer.remove(0, end + 1);
        }
    }
    QProcess m_process;
    QByteArray m_buffer;
    QByteArray m_err;
    QList<QJsonObject> m_lines;
};

int count(const QList<QJsonObject> &lines, const QString &type, const QString &watch, const QString &status = {}, qsizetype from = 0)
{
    int n = 0;
    for (qsizetype i = from; i < lines.size(); ++i) {
        const QJsonObject &o = lines.at(i);
        if (o.value(QLatin1String("type")).toString() == type && o.value(QLatin1String("watch")).toString() == watch
            && (status.isEmpty() || o.value(QLatin1String("status")).toString() == status))
            ++n;
    }
    return n;
}

} // namespace

class TestCliWatch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void threeDevicesOnThreeLinks();
    void brokenSessionRefused();
    void noWatches();
};

void TestCliWatch::threeDevicesOnThreeLinks()
{
    QString why;
    if (!mbscope::testpeers::socatAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());

    Background gamma;
    QVERIFY2(gamma.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"),
                          QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet")}, &why),
             qPrintable(why));
    const QString plcUrl = QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort());
    const QStringList plcArguments{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("m221-plc"),
                                   QStringLiteral("--listen"), plcUrl, QStringLiteral("--quiet")};
    auto plc = std::make_unique<Background>();
    QVERIFY2(plc->start(plcArguments, &why), qPrintable(why));
    mbscope::testpeers::PtyPair pty;
    QVERIFY2(pty.start(), qPrintable(pty.error()));
    Background arduino;
    QVERIFY2(arduino.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"),
                            QStringLiteral("--listen"), QStringLiteral("rtu://%1?baud=9600&parity=N").arg(pty.peerEnd()),
                            QStringLiteral("--quiet")}, &why),
             qPrintable(why));

    const QString session = dir.filePath(QStringLiteral("bench.mbscope.json"));
    const QString arduinoUrl = QStringLiteral("rtu://%1?baud=9600&parity=N").arg(pty.ourEnd());
    const QString json = QStringLiteral(R"({
  "format": "mbscope-session", "version": 2, "name": "three devices",
  "watches": [
    {"name": "gamma", "target": "%1", "address": "0x0079", "quantity": 14, "intervalMs": 100,
     "points": [{"address": "0x0079", "name": "high voltage", "unit": "V"},
                {"address": "0x007F", "name": "measuring time", "scale": 0.001, "unit": "s"},
                {"address": "0x0086", "name": "counts", "unit": "counts"}],
     "rules": [{"point": "counts", "above": 50, "forPolls": 2, "severity": "alarm"}]},
    {"name": "plc", "target": "%2", "address": 0, "quantity": 4, "intervalMs": 100},
    {"name": "arduino", "target": "%3", "address": 0, "quantity": 4, "intervalMs": 200,
     "points": [{"address": 0, "name": "analog input 1"}, {"address": 3, "name": "digital output",
                 "bitFields": [{"name": "relay", "bits": 0, "states": ["off", "on"]}]}]}
  ],
  "watchLinks": [{"target": "%2", "reconnectMinMs": 100, "reconnectMaxMs": 400},
                 {"target": "%3", "gapMs": 10}]
})").arg(gamma.url(), plcUrl, arduinoUrl);
    QVERIFY(writeFile(session, json.toUtf8()));

    WatchProcess watch;
    const QString csvDir = dir.filePath(QStringLiteral("logs"));
    QVERIFY(watch.start({QStringLiteral("watch"), session, QStringLiteral("--json"), QStringLiteral("--csv"), csvDir}));
    // All three answer, and the gamma detector's counts fire the rule.
    QVERIFY2(watch.waitFor([](const QList<QJsonObject> &l) {
        return count(l, QStringLiteral("sample"), QStringLiteral("gamma"), QStringLiteral("ok")) >= 3
            && count(l, QStringLiteral("sample"), QStringLiteral("plc"), QStringLiteral("ok")) >= 3
            && count(l, QStringLiteral("sample"), QStringLiteral("arduino"), QStringLiteral("ok")) >= 3
            && count(l, QStringLiteral("rule"), QStringLiteral("gamma")) >= 1;
    }), watch.err().constData());
    bool checkedGamma = false;
    bool checkedArduino = false;
    for (const QJsonObject &o : watch.lines()) {
        const QString name = o.value(QLatin1String("watch")).toString();
        if (o.value(QLatin1String("type")).toString() == QLatin1String("rule")) {
            QCOMPARE(o.value(QLatin1String("event")).toString(), QStringLiteral("fired"));
            QCOMPARE(o.value(QLatin1String("severity")).toString(), QStringLiteral("alarm"));
            QCOMPARE(o.value(QLatin1String("message")).toString(), QStringLiteral("counts above 50 counts for 2 polls"));
            QVERIFY(o.value(QLatin1String("value")).toDouble() > 50);
        }
        if (o.value(QLatin1String("status")).toString() != QLatin1String("ok"))
            continue;
        const QJsonArray values = o.value(QLatin1String("values")).toArray();
        if (name == QLatin1String("gamma")) {
            QCOMPARE(values.size(), 14);
            QCOMPARE(values.at(0)[QLatin1String("name")].toString(), QStringLiteral("high voltage"));
            QCOMPARE(values.at(0)[QLatin1String("value")].toDouble(), 1050.0);
            QCOMPARE(values.at(6)[QLatin1String("value")].toDouble(), 1.0); // 1000 ms as s
            QCOMPARE(values.at(6)[QLatin1String("unit")].toString(), QStringLiteral("s"));
            checkedGamma = true;
        } else if (name == QLatin1String("arduino")) {
            const double analog = values.at(0)[QLatin1String("value")].toDouble();
            QVERIFY2(analog >= 61 && analog <= 77, qPrintable(QString::number(analog)));
            QCOMPARE(values.at(3)[QLatin1String("bit_fields")][QLatin1String("relay")].toString(), QStringLiteral("on"));
            checkedArduino = true;
        }
    }
    QVERIFY(checkedGamma && checkedArduino);

    // The PLC goes away: its polls fail, the other two go on.
    plc->stop();
    plc.reset();
    const qsizetype killedAt = watch.lines().size();
    QVERIFY2(watch.waitFor([&](const QList<QJsonObject> &l) {
        return count(l, QStringLiteral("sample"), QStringLiteral("plc"), QStringLiteral("error"), killedAt) >= 2
            && count(l, QStringLiteral("sample"), QStringLiteral("gamma"), QStringLiteral("ok"), killedAt) >= 5
            && count(l, QStringLiteral("sample"), QStringLiteral("arduino"), QStringLiteral("ok"), killedAt) >= 3;
    }), watch.err().constData());

    // It comes back on the same port: the link opens again, counted.
    plc = std::make_unique<Background>();
    QVERIFY2(plc->start(plcArguments, &why), qPrintable(why));
    const qsizetype backAt = watch.lines().size();
    QVERIFY2(watch.waitFor([&](const QList<QJsonObject> &l) {
        return count(l, QStringLiteral("sample"), QStringLiteral("plc"), QStringLiteral("ok"), backAt) >= 3;
    }), watch.err().constData());

    QCOMPARE(watch.stop(SIGTERM), 1); // some polls failed
    const QJsonObject summary = watch.lines().constLast();
    QCOMPARE(summary.value(QLatin1String("type")).toString(), QStringLiteral("summary"));
    const QJsonArray counters = summary.value(QLatin1String("watches")).toArray();
    QCOMPARE(counters.size(), 3);
    const QJsonObject gammaCounters = counters.at(0).toObject();
    const QJsonObject plcCounters = counters.at(1).toObject();
    const QJsonObject arduinoCounters = counters.at(2).toObject();
    QCOMPARE(gammaCounters.value(QLatin1String("watch")).toString(), QStringLiteral("gamma"));
    QCOMPARE(gammaCounters.value(QLatin1String("ok")).toDouble(), gammaCounters.value(QLatin1String("polls")).toDouble());
    QVERIFY(gammaCounters.value(QLatin1String("rule_firings")).toDouble() >= 1);
    QCOMPARE(arduinoCounters.value(QLatin1String("ok")).toDouble(), arduinoCounters.value(QLatin1String("polls")).toDouble());
    QCOMPARE(plcCounters.value(QLatin1String("reconnects")).toDouble(), 1.0);
    QVERIFY(plcCounters.value(QLatin1String("link_errors")).toDouble() >= 2);
    QCOMPARE(plcCounters.value(QLatin1String("polls")).toDouble(),
             plcCounters.value(QLatin1String("ok")).toDouble() + plcCounters.value(QLatin1String("link_errors")).toDouble());
    // The counters agree with the lines printed.
    QCOMPARE(plcCounters.value(QLatin1String("polls")).toDouble(), double(count(watch.lines(), QStringLiteral("sample"), QStringLiteral("plc"))));
    bool sawReconnect = false;
    for (const QJsonObject &o : watch.lines()) {
        if (o.value(QLatin1String("type")).toString() == QLatin1String("link") && o.value(QLatin1String("target")).toString() == plcUrl
            && o.value(QLatin1String("state")).toString() == QLatin1String("up") && o.value(QLatin1String("reconnects")).toInt() == 1)
            sawReconnect = true;
    }
    QVERIFY(sawReconnect);

    // A CSV file per watch, with the header's names and units and a row per poll (flushed at SIGTERM).
    const QStringList files = QDir(csvDir).entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name);
    QCOMPARE(files.size(), 3);
    QVERIFY(files.at(0).startsWith(QLatin1String("arduino-")));
    QFile gammaCsv(QDir(csvDir).filePath(files.at(1)));
    QVERIFY(gammaCsv.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = gammaCsv.readAll().split('\n');
    QVERIFY(rows.first().startsWith("time,status,high voltage [V],0x007A,"));
    QVERIFY(rows.first().endsWith(",counts [counts],error"));
    QCOMPARE(double(rows.size() - 2), gammaCounters.value(QLatin1String("polls")).toDouble()); // header, rows, the final newline
    QFile plcCsv(QDir(csvDir).filePath(files.at(2)));
    QVERIFY(plcCsv.open(QIODevice::ReadOnly));
    QVERIFY(plcCsv.readAll().contains(",error,,,,,"));
}

void TestCliWatch::brokenSessionRefused()
{
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("broken.mbscope.json"));
    const QByteArray json = R"({"format": "mbscope-session", "version": 2, "watches": [
        {"name": "a", "target": "tcp://127.0.0.1:5020", "address": 0, "quantity": 4,
         "rules": [{"point": "0", "above": 1, "forPolls": 0}]}]})";
    QVERIFY(writeFile(session, json));
    const CliResult r = runMbscope({QStringLiteral("watch"), session});
    QVERIFY2(r.finished, r.describe().constData());
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.errText().contains(QStringLiteral("broken.mbscope.json: watches[0].rules[0].forPolls: 0 is below 1")),
             r.describe().constData());
    QVERIFY(r.out.isEmpty());
}

void TestCliWatch::noWatches()
{
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("plain.mbscope.json"));
    const QByteArray json = R"({"format": "mbscope-session", "version": 1, "name": "no watches"})";
    QVERIFY(writeFile(session, json));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--json")});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.errText().contains(QStringLiteral("the session has no watches")), r.describe().constData());
    // --json: the error object on standard output.
    QVERIFY2(r.json().value(QLatin1String("error")).toObject().value(QLatin1String("message")).toString().contains(QLatin1String("no watches")),
             r.describe().constData());
}

QTEST_GUILESS_MAIN(TestCliWatch)
#include "tst_cli_watch.moc"
