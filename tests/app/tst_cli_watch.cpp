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
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <functional>

using namespace mbscope::testcli;

namespace {

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

// `mbscope simulate --profile conformance` listening on listen ("tcp://127.0.0.1:0": a free port).
bool startConformance(Background &sim, const QString &listen, QString *why)
{
    return sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"), listen,
                      QStringLiteral("--quiet")},
                     why);
}

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
    void linkWaitsTheWarmUp();
    void closeEachIsNoReconnect();
    void brokenSessionRefused();
    void thresholdsThePointCannotReachRefused();
    void noWatches();
    void csvFailureSaidOnceAndCounted();
    void fifoWatch();
    void linkErrorSaidOnce();
    void unreachableBrokerHasItsOwnStatus();
    void firstConnectionIsNoReconnect();
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

    // A CSV file per watch, with the header's names and units and a row per poll (flushed at
    // SIGTERM), and one of rule events for the watch whose rule fired.
    QStringList files = QDir(csvDir).entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name);
    QCOMPARE(files.size(), 4);
    QCOMPARE(summary.value(QLatin1String("csv_files")).toArray().size(), 4);
    QVERIFY(files.at(0).startsWith(QLatin1String("arduino-")));
    QVERIFY2(files.at(2).startsWith(QLatin1String("gamma-events-")), qPrintable(files.at(2)));
    QFile eventsCsv(QDir(csvDir).filePath(files.at(2)));
    QVERIFY(eventsCsv.open(QIODevice::ReadOnly));
    const QList<QByteArray> events = eventsCsv.readAll().split('\n');
    QCOMPARE(events.first(), QByteArray("time,event,severity,rule,point,value,message,fired"));
    QCOMPARE(qsizetype(events.size() - 2), count(watch.lines(), QStringLiteral("rule"), QStringLiteral("gamma")));
    const QList<QByteArray> fired = events.at(1).split(',');
    QCOMPARE(fired.size(), 8);
    QCOMPARE(fired.at(1), QByteArray("fired"));
    QCOMPARE(fired.at(2), QByteArray("alarm"));
    QCOMPARE(fired.at(3), QByteArray("0"));
    QCOMPARE(fired.at(4), QByteArray("counts"));
    QVERIFY(fired.at(5).toDouble() > 50);
    QCOMPARE(fired.at(6), QByteArray("counts above 50 counts for 2 polls"));
    QCOMPARE(fired.at(7), QByteArray("1"));
    files.removeAt(2);
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

// Issue 26 item 4, the file's side: a threshold the rule's point can never reach (a mask wider than
// the register, a coil equal to 2) is refused with its JSON path, not run as a rule that never fires.
void TestCliWatch::thresholdsThePointCannotReachRefused()
{
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("thresholds.mbscope.json"));
    const QByteArray json = R"({"format": "mbscope-session", "version": 2, "watches": [
        {"name": "words", "target": "tcp://127.0.0.1:1", "address": 0, "quantity": 4,
         "points": [{"address": 0, "name": "status"}, {"address": 2, "name": "total", "format": "u32"}],
         "rules": [{"point": "status", "bits": 65536}, {"point": "total", "bits": 65536}, {"point": "status", "above": 10}]},
        {"name": "coils", "target": "tcp://127.0.0.1:1", "function": 1, "address": 0, "quantity": 8,
         "rules": [{"point": "3", "equal": 2}, {"point": "4", "bits": 2}, {"point": "5", "equal": 1}]}]})";
    QVERIFY(writeFile(session, json));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("1")});
    QVERIFY2(r.finished, r.describe().constData());
    QCOMPARE(r.exitCode, 2);
    const QString err = r.errText();
    QVERIFY2(err.contains(QStringLiteral("thresholds.mbscope.json: watches[0].rules[0].bits: mask 0x10000 has bits beyond the 16 bit(s) of 'status' (at most 0xFFFF)")),
             r.describe().constData());
    QVERIFY2(err.contains(QStringLiteral("watches[1].rules[0].equal: 2 is not 0 or 1")), r.describe().constData());
    QVERIFY2(err.contains(QStringLiteral("watches[1].rules[1].bits: mask 0x2 has bits beyond the 1 bit(s) of '4'")), r.describe().constData());
    // The 32-bit point takes the mask; the sensible rules are not named.
    QVERIFY2(!err.contains(QStringLiteral("rules[1].bits: mask 0x10000")), r.describe().constData());
    QVERIFY2(!err.contains(QStringLiteral("watches[0].rules[2]")) && !err.contains(QStringLiteral("watches[1].rules[2]")),
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

// The CSV folder made impossible while logging (a file put where it was; the log rolls every few
// rows, so it needs the folder again): said once on standard error, levelled, while the polls go
// on; the rows lost are counted when the files close, and the exit status says it.
void TestCliWatch::csvFailureSaidOnceAndCounted()
{
    QString why;
    Background sim;
    QVERIFY2(startConformance(sim, QStringLiteral("tcp://127.0.0.1:0"), &why), qPrintable(why));
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("plant.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "plant", "target": "%1", "address": 0, "quantity": 4, "intervalMs": 50},
              {"name": "pump", "target": "%1", "address": 4, "quantity": 4, "intervalMs": 70},
              {"name": "tank", "target": "%1", "address": 8, "quantity": 4, "intervalMs": 90}],
  "watchLog": {"directory": "logs", "rollBytes": 200}})").arg(sim.url()).toUtf8()));
    WatchProcess watch;
    QVERIFY(watch.start({QStringLiteral("watch"), session, QStringLiteral("--json")}));
    QVERIFY2(watch.waitFor([](const QList<QJsonObject> &l) { return count(l, QStringLiteral("sample"), QStringLiteral("plant"), QStringLiteral("ok")) >= 4; }),
             watch.err().constData());
    const QString logs = dir.filePath(QStringLiteral("logs"));
    QVERIFY(QDir().rename(logs, dir.filePath(QStringLiteral("moved"))));
    QVERIFY(writeFile(logs, "not a folder"));
    const qsizetype from = watch.lines().size();
    QVERIFY2(watch.waitFor([from](const QList<QJsonObject> &l) {
        return count(l, QStringLiteral("sample"), QStringLiteral("plant"), QStringLiteral("ok"), from) >= 10;
    }), watch.err().constData());
    QCOMPARE(watch.stop(SIGTERM), 1);
    const QString err = QString::fromUtf8(watch.err());
    QCOMPARE(err.count(QStringLiteral("the log directory cannot be made")), 1);
    QVERIFY2(err.contains(QStringLiteral("CSV: %1: the log directory cannot be made (polling goes on; the rows lost are counted)").arg(logs)),
             qPrintable(err));
    static const QRegularExpression lost(QStringLiteral(R"(CSV: (\d+) rows? could not be written)"));
    const QRegularExpressionMatch m = lost.match(err);
    QVERIFY2(m.hasMatch(), qPrintable(err));
    QVERIFY(m.captured(1).toInt() >= 8);
    // The rows before the failure are in the files that were moved.
    qsizetype rows = 0;
    for (const QString &name : QDir(dir.filePath(QStringLiteral("moved"))).entryList({QStringLiteral("*.csv")}, QDir::Files)) {
        QFile f(QDir(dir.filePath(QStringLiteral("moved"))).filePath(name));
        QVERIFY(f.open(QIODevice::ReadOnly));
        rows += f.readAll().count('\n') - 1;
    }
    QVERIFY(rows >= 4);
    // Every poll is a row written or a row counted as lost.
    // Said once for the three watches, though each fails at its own roll while the others still
    // write to their open files (it was said once a watch).
    const QJsonObject summary = watch.lines().constLast();
    double polls = 0;
    for (const QJsonValue &w : summary.value(QLatin1String("watches")).toArray())
        polls += w[QLatin1String("polls")].toDouble();
    QCOMPARE(double(rows + m.captured(1).toInt()), polls);
}

// A watch of function 0x18 (Read FIFO Queue) against the simulator's FIFO (conformance profile:
// pointer 0x04DE, the values 0x01B8 and 0x1284 of V1.1b3 6.18's example) through `mbscope watch`:
// the values named from the pointer's address in the JSON lines, and the CSV's columns as many as
// the quantity allows, the two values filled and the rest empty.
void TestCliWatch::fifoWatch()
{
    QString why;
    Background sim;
    QVERIFY2(startConformance(sim, QStringLiteral("tcp://127.0.0.1:0"), &why), qPrintable(why));
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("fifo.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "queue", "target": "%1", "function": 24, "address": "0x04DE", "quantity": 4, "intervalMs": 50,
               "points": [{"address": "0x04DE", "name": "reading", "format": "hex"}]}]})").arg(sim.url()).toUtf8()));
    const QString csvDir = dir.filePath(QStringLiteral("logs"));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--json"), QStringLiteral("--count"), QStringLiteral("3"),
                                    QStringLiteral("--csv"), csvDir});
    QVERIFY2(r.finished, r.describe().constData());
    QCOMPARE(r.exitCode, 0);
    int samples = 0;
    for (const QByteArray &line : r.out.split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        if (o.value(QLatin1String("type")).toString() != QLatin1String("sample"))
            continue;
        ++samples;
        QCOMPARE(o.value(QLatin1String("status")).toString(), QStringLiteral("ok"));
        const QJsonArray values = o.value(QLatin1String("values")).toArray();
        QCOMPARE(values.size(), 2);
        QCOMPARE(values.at(0)[QLatin1String("name")].toString(), QStringLiteral("reading"));
        QCOMPARE(values.at(0)[QLatin1String("text")].toString(), QStringLiteral("0x01B8"));
        QCOMPARE(values.at(1)[QLatin1String("address")].toInt(), 0x04DF);
        QCOMPARE(values.at(1)[QLatin1String("value")].toInt(), 0x1284);
    }
    QCOMPARE(samples, 3);
    const QStringList files = QDir(csvDir).entryList({QStringLiteral("*.csv")}, QDir::Files);
    QCOMPARE(files.size(), 1);
    QFile csv(QDir(csvDir).filePath(files.constFirst()));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = csv.readAll().split('\n');
    QCOMPARE(rows.size(), 5); // the header, three rows, the final newline
    QCOMPARE(rows.at(0).split(',').size(), 2 + 4 + 1);
    QVERIFY2(rows.at(0).startsWith("time,status,reading,"), rows.at(0).constData());
    for (int i = 1; i <= 3; ++i)
        QVERIFY2(rows.at(i).endsWith(",ok,0x01B8,4740,,,"), rows.at(i).constData()); // two values, two empty, no error
}

// A link that fails is said once on standard error, by the service's levelled log ("warning:
// link ...: down: ..."), not again as a "mbscope watch: ... error:" line for each poll it costs
// (four here), nor as a line per attempt to open it again; the counters say the polls lost.
void TestCliWatch::linkErrorSaidOnce()
{
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("gone.mbscope.json"));
    const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort());
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "gone", "target": "%1", "address": 0, "quantity": 2, "intervalMs": 100}],
  "watchLinks": [{"target": "%1", "reconnectMinMs": 100, "reconnectMaxMs": 100}]})").arg(target).toUtf8()));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("4")});
    QVERIFY2(r.finished, r.describe().constData());
    QCOMPARE(r.exitCode, 1);
    const QString err = r.errText();
    QVERIFY2(err.split(QLatin1Char('\n')).filter(QStringLiteral("connection refused")).size() == 1, qPrintable(err));
    QVERIFY2(err.contains(QStringLiteral(" warning: link %1: down: %1: connection refused").arg(target)), qPrintable(err));
    QVERIFY2(!err.contains(QStringLiteral("next attempt")), qPrintable(err));
    QVERIFY2(r.outText().contains(QStringLiteral("gone: 4 polls, 0 ok")), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("4 link errors")), r.describe().constData());
}

// Issue 26 item 10: with --mqtt naming a broker nothing listens for, watch polled, published
// nothing and ended with exit status 0. It says what was lost and ends with 3; failed polls still
// end with 1.
void TestCliWatch::unreachableBrokerHasItsOwnStatus()
{
    QString why;
    Background sim;
    QVERIFY2(startConformance(sim, QStringLiteral("tcp://127.0.0.1:0"), &why), qPrintable(why));
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("plant.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "plant", "target": "%1", "address": 0, "quantity": 2, "intervalMs": 50}]})").arg(sim.url()).toUtf8()));
    const QString broker = QStringLiteral("mqtt://127.0.0.1:%1").arg(closedPort());
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("3"), QStringLiteral("--mqtt"), broker});
    QVERIFY2(r.finished && r.exitCode == 3, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("plant: 3 polls, 3 ok")), r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral(" error: MQTT: the broker at %1 was never reached: ").arg(broker)), r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral(" not published")), r.describe().constData());
    // --json: the same status.
    const CliResult json = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("2"), QStringLiteral("--mqtt"),
                                       broker, QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 3, json.describe().constData());
    // Without --mqtt: 0.
    const CliResult plain = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("2")});
    QVERIFY2(plain.finished && plain.exitCode == 0, plain.describe().constData());
}

// Issue 26 item 12: a link down from the start that came up said "up again (reconnect 0)": it
// was never up before. It says its first connection came after the attempts that failed.
void TestCliWatch::firstConnectionIsNoReconnect()
{
    QTemporaryDir dir;
    const quint16 port = closedPort();
    const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
    const QString session = dir.filePath(QStringLiteral("late.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "late", "target": "%1", "address": 0, "quantity": 2, "intervalMs": 50}],
  "watchLinks": [{"target": "%1", "reconnectMinMs": 50, "reconnectMaxMs": 50}]})").arg(target).toUtf8()));
    WatchProcess watch;
    QVERIFY(watch.start({QStringLiteral("watch"), session, QStringLiteral("--json")}));
    QVERIFY2(watch.waitFor([](const QList<QJsonObject> &l) { return count(l, QStringLiteral("sample"), QStringLiteral("late"), QStringLiteral("error")) >= 2; }),
             watch.err().constData());
    QString why;
    Background sim;
    QVERIFY2(startConformance(sim, target, &why), qPrintable(why));
    QVERIFY2(watch.waitFor([](const QList<QJsonObject> &l) { return count(l, QStringLiteral("sample"), QStringLiteral("late"), QStringLiteral("ok")) >= 2; }),
             watch.err().constData());
    QCOMPARE(watch.stop(SIGTERM), 1); // the polls lost before the link came up
    const QString err = QString::fromUtf8(watch.err());
    QVERIFY2(!err.contains(QStringLiteral("reconnect 0")), qPrintable(err));
    static const QRegularExpression first(QStringLiteral(R"( notice: link tcp://127\.0\.0\.1:\d+: up \(first connection, after \d+ failed attempts?\))"));
    QVERIFY2(first.match(err).hasMatch(), qPrintable(err));
    QCOMPARE(watch.lines().constLast().value(QLatin1String("watches")).toArray().at(0)[QLatin1String("reconnects")].toInt(), 0);
}

// Issue 28: a device that ignores requests in the first 400 ms of a connection (limits.warmUpMs, as
// the timing scan records it). The session's link waits its warmUpMs (500) after opening before the
// first request, and every poll is answered: exit 0 (before, warmUpMs was refused as an unknown
// member; without the wait, the first request goes unanswered and the watch counts a timeout).
// The gap too (minGapMs 40, busy answers sooner): the link's gapMs 41, kept by the engine as for
// every other talker (the watch link kept it with timers of its own), gets every poll answered.
void TestCliWatch::linkWaitsTheWarmUp()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString profile = dir.filePath(QStringLiteral("slow.json"));
    QVERIFY(writeFile(profile, R"({"name": "slow", "limits": {"warmUpMs": 400, "minGapMs": 40},
        "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 4}]}}]})"));
    Background sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile, QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &why),
             qPrintable(why));
    const QString session = dir.filePath(QStringLiteral("slow.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2, "name": "slow",
        "watches": [{"name": "slow", "target": "%1", "address": 0, "quantity": 4, "intervalMs": 10},
                    {"name": "slow too", "target": "%1", "address": 1, "quantity": 2, "intervalMs": 10}],
        "watchLinks": [{"target": "%1", "warmUpMs": 500, "gapMs": 41, "timeoutMs": 300}]})")
                                   .arg(sim.url())
                                   .toUtf8()));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("3"), QStringLiteral("--quiet")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
}

// A device that hangs up after each answer, on a target with close=each: a new connection per
// request is the plan, not a reconnect (a new user's try saw "up" twice a poll and 8 reconnects).
void TestCliWatch::closeEachIsNoReconnect()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString profile = dir.filePath(QStringLiteral("hang.json"));
    QVERIFY(writeFile(profile, R"({"name": "hang", "limits": {"closesAfterAnswer": true},
        "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 4}]}}]})"));
    Background sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile, QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &why),
             qPrintable(why));
    const QString target = sim.url() + QStringLiteral("?close=each");
    const QString session = dir.filePath(QStringLiteral("hang.mbscope.json"));
    QVERIFY(writeFile(session, QStringLiteral(R"({"format": "mbscope-session", "version": 2, "name": "hang",
        "watches": [{"name": "a", "target": "%1", "address": 0, "quantity": 2, "intervalMs": 20},
                    {"name": "b", "target": "%1", "address": 2, "quantity": 2, "intervalMs": 20}]})")
                                   .arg(target)
                                   .toUtf8()));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("5"), QStringLiteral("--quiet")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    QCOMPARE(r.errText().count(QLatin1String(": up\n")) + r.outText().count(QLatin1String(": up\n")), 1);
    QVERIFY2(r.outText().count(QLatin1String(", 0 timeouts,")) == 2 && r.outText().count(QLatin1String(", 0 reconnects,")) == 2,
             r.describe());
}

QTEST_GUILESS_MAIN(TestCliWatch)
#include "tst_cli_watch.moc"
