// Every command records (issue 13, item 4): `--record FILE` journals what a command sent and got,
// with the command, target and requests in the journal's metadata, so the journal alone is enough
// for analyze, export and replay. Against `mbscope simulate --profile rosrao-gamma` on loopback:
// a recorded poll analysed with the counts poll printed, replayed with no --target, exported to
// pcapng that tshark decodes; a recording poll killed with SIGKILL and its cut journal recovered;
// simulate --record (both directions, fault notes); poll --print values and --csv; an existing
// journal refused; a poll or monitor whose link never came up leaves no journal (tryout 8, item 2);
// watch and scan record too (issue 25): a watch of two links in one journal, each link's
// transactions paired on their own, and a unit scan, both analysed and replayed.

#include "clitest.h"

#include "traffic/trafficjournal.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QTest>

#include <csignal>
#include <memory>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

// The rosrao-gamma settings block of unit 1 (V1.1b3 6.3: 22 holding registers at 0x0079), as
// tst_cli_replay reads it: no live value in it.
const QStringList kSettingsRead = {QStringLiteral("--unit"), QStringLiteral("1"), QStringLiteral("--function"), QStringLiteral("3"),
                                   QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("22")};

int recordedTransactions(const QByteArray &err, const QString &path)
{
    const QRegularExpression line(QStringLiteral("recorded ([0-9,]+) frames \\(([0-9,]+) transactions?\\) to ")
                                  + QRegularExpression::escape(path));
    const QRegularExpressionMatch m = line.match(QString::fromUtf8(err));
    return m.hasMatch() ? m.captured(2).remove(QLatin1Char(',')).toInt() : -1;
}

} // namespace

class TestCliRecord : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void pollRecordedThenAnalyzed();
    void journalReplayedWithoutTarget();
    void journalExportedForTshark();
    void killedPollRecovered();
    void simulateRecords();
    void simulateReadyFile();
    void simulateReadyFileRefused();
    void exchangeCommandsRecord();
    void runRecordsIntoTheSessionsCapture();
    void existingJournalRefused();
    void unreachableTargetLeavesNoJournal();
    void pollPrintsValuesAndCsv();
    void watchRecordsEveryLink();
    void scanRecords();

private:
    QTemporaryDir m_dir;
    Background m_sim;
    QString m_journal;
    QJsonObject m_poll;
};

void TestCliRecord::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QString error;
    QVERIFY2(m_sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                          QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                         &error),
             qPrintable(error));
    m_journal = m_dir.filePath(QStringLiteral("poll.mbscope.journal"));
}

void TestCliRecord::pollRecordedThenAnalyzed()
{
    const CliResult r = runMbscope(QStringList{QStringLiteral("poll"), QStringLiteral("--target"), m_sim.url()} + kSettingsRead
                                   + QStringList{QStringLiteral("--interval"), QStringLiteral("5ms"), QStringLiteral("--count"),
                                                 QStringLiteral("200"), QStringLiteral("--json"), QStringLiteral("--record"), m_journal});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    m_poll = r.json();
    QCOMPARE(m_poll.value(QStringLiteral("count")).toInt(), 200);
    QCOMPARE(recordedTransactions(r.err, m_journal), 200);
    QVERIFY2(r.errText().contains(QStringLiteral("recorded 400 frames (200 transactions) to ") + m_journal), r.describe().constData());

    const CliResult a = runMbscope({QStringLiteral("analyze"), m_journal, QStringLiteral("--json")});
    QVERIFY2(a.finished && a.exitCode == 0, a.describe().constData());
    const QJsonObject o = a.json();
    for (const char *key : {"count", "ok", "exceptions", "timeouts"})
        QCOMPARE(o.value(QLatin1String(key)).toInt(), m_poll.value(QLatin1String(key)).toInt());
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("version")).toInt(), 3); // version 3: closed with an end record
    QCOMPARE(source.value(QStringLiteral("frames")).toInt(), 400);
    const QJsonObject metadata = source.value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("poll"));
    QCOMPARE(metadata.value(QStringLiteral("role")).toString(), QStringLiteral("client"));
    QCOMPARE(metadata.value(QStringLiteral("target")).toString(), m_sim.url());
    QVERIFY(!metadata.value(QStringLiteral("host")).toString().isEmpty());
    QVERIFY(metadata.value(QStringLiteral("arguments")).toArray().contains(QStringLiteral("--record")));
    const QJsonArray requests = metadata.value(QStringLiteral("requests")).toArray();
    QCOMPARE(requests.size(), 1);
    QVERIFY2(requests.at(0).toObject().value(QStringLiteral("hex")).toString().endsWith(QStringLiteral("01 03 00 79 00 16")),
             qPrintable(requests.at(0).toObject().value(QStringLiteral("hex")).toString()));
    QCOMPARE(metadata.value(QStringLiteral("settings")).toObject().value(QStringLiteral("count")).toInt(), 200);

    // The text says what the journal recorded.
    const CliResult text = runMbscope({QStringLiteral("analyze"), m_journal});
    QVERIFY2(text.outText().contains(QRegularExpression(QStringLiteral("\nrecorded +poll by mbscope [0-9.]+ on "))), text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("\ntarget        ") + m_sim.url() + QLatin1Char('\n')), text.describe().constData());
}

void TestCliRecord::journalReplayedWithoutTarget()
{
    if (m_poll.isEmpty())
        QSKIP("needs the recorded poll");
    const CliResult r = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--speed"), QStringLiteral("max")});
    QVERIFY2(r.finished && (r.exitCode == 0 || r.exitCode == 1), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral(" to %1 (the target the journal recorded").arg(m_sim.url())), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("replayed      200 of 200 requests")), r.describe().constData());

    const CliResult j = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--speed"), QStringLiteral("max"), QStringLiteral("--json"),
                                    QStringLiteral("--record"), m_dir.filePath(QStringLiteral("replayed.mbscope.journal"))});
    QVERIFY2(j.finished && (j.exitCode == 0 || j.exitCode == 1), j.describe().constData());
    const QJsonObject o = j.json();
    QCOMPARE(o.value(QStringLiteral("replayed")).toInt(), 200);
    QCOMPARE(o.value(QStringLiteral("outcome_differs")).toInt(), 0);
    QCOMPARE(o.value(QStringLiteral("missing_answers")).toInt(), 0);
    // No differences but the live register: the detector's count at 0x0086 (rosrao-gamma's
    // counter generator), which moves between the recording and the replay.
    for (const QJsonValue &row : o.value(QStringLiteral("differences")).toArray()) {
        for (const QJsonValue &difference : row.toObject().value(QStringLiteral("differences")).toArray())
            QVERIFY2(difference.toString().startsWith(QStringLiteral("modbus.register_value@0x0086: ")), qPrintable(difference.toString()));
    }
    QCOMPARE(o.value(QStringLiteral("matched")).toInt() + o.value(QStringLiteral("values_differ")).toInt(), 200);
    QCOMPARE(j.exitCode, o.value(QStringLiteral("values_differ")).toInt() > 0 ? 1 : 0);
    QVERIFY2(j.errText().contains(QStringLiteral("no --target: replaying to ") + m_sim.url()), j.describe().constData());
    QCOMPARE(recordedTransactions(j.err, m_dir.filePath(QStringLiteral("replayed.mbscope.journal"))), 200);
}

void TestCliRecord::journalExportedForTshark()
{
    if (m_poll.isEmpty())
        QSKIP("needs the recorded poll");
    const QString pcap = m_dir.filePath(QStringLiteral("poll.pcapng"));
    const CliResult e = runMbscope({QStringLiteral("export"), m_journal, QStringLiteral("--pcap"), pcap});
    QVERIFY2(e.finished && e.exitCode == 0, e.describe().constData());
    if (QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty())
        QSKIP("tshark is not installed (Debian: apt-get install tshark)");
    QStringList arguments{QStringLiteral("-r"), pcap};
    // The option export prints for a port tshark does not know ("port N (Modbus TCP): -o mbtcp.tcp.port:N").
    for (const QString &line : e.outText().split(QLatin1Char('\n'))) {
        if (line.contains(QLatin1String("): -")))
            arguments << line.section(QStringLiteral(": "), 1).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    }
    arguments << QStringLiteral("-Y") << QStringLiteral("modbus") << QStringLiteral("-T") << QStringLiteral("fields") << QStringLiteral("-e")
              << QStringLiteral("modbus.func_code") << QStringLiteral("-e") << QStringLiteral("modbus.reference_num") << QStringLiteral("-e")
              << QStringLiteral("modbus.request_frame");
    QProcess tshark;
    tshark.start(QStringLiteral("tshark"), arguments);
    QVERIFY(tshark.waitForFinished(120000));
    QVERIFY2(tshark.exitCode() == 0, tshark.readAllStandardError().constData());
    int requests = 0, responses = 0;
    for (const QByteArray &line : tshark.readAllStandardOutput().split('\n')) {
        if (line.isEmpty())
            continue;
        const QList<QByteArray> fields = line.split('\t');
        QCOMPARE(fields.value(0), QByteArray("3"));
        if (fields.value(1) == "121")
            ++requests; // tshark shows the reference number on requests
        else if (!fields.value(2).isEmpty())
            ++responses; // and on answers the request it paired them with
    }
    QCOMPARE(requests, 200);
    QCOMPARE(responses, m_poll.value(QStringLiteral("ok")).toInt());
}

void TestCliRecord::killedPollRecovered()
{
    // A recording poll with no end, killed with SIGKILL while it runs.
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const QString journal = m_dir.filePath(QStringLiteral("killed.mbscope.journal"));
    QProcess poll;
    poll.start(mbscopePath(), QStringList{QStringLiteral("poll"), QStringLiteral("--target"), sim.url()} + kSettingsRead
                                  + QStringList{QStringLiteral("--interval"), QStringLiteral("0"), QStringLiteral("--record"), journal});
    QVERIFY(poll.waitForStarted(30000));
    // Until several batches are on disk (1,024 frames each), then a little more.
    QElapsedTimer waited;
    waited.start();
    while (QFileInfo(journal).size() < 200'000 && waited.elapsed() < 60000)
        QThread::msleep(20);
    QThread::msleep(300);
    ::kill(pid_t(poll.processId()), SIGKILL);
    QVERIFY(poll.waitForFinished(10000));
    QCOMPARE(poll.exitStatus(), QProcess::CrashExit);
    QByteArray simErr;
    const QByteArray simOut = sim.stop(&simErr);
    const QRegularExpressionMatch served = QRegularExpression(QStringLiteral("interrupted: (\\d+) requests in")).match(QString::fromUtf8(simOut));
    QVERIFY2(served.hasMatch(), simOut.constData());
    const int answered = served.captured(1).toInt();

    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished && (a.exitCode == 0 || a.exitCode == 1), a.describe().constData());
    const QJsonObject o = a.json();
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QVERIFY2(source.value(QStringLiteral("recovery")).toString().startsWith(QStringLiteral("recovered ")), a.describe().constData());
    // Killed: never closed (no end record), so never complete, whether a batch was cut or not.
    QVERIFY2(!source.value(QStringLiteral("complete")).toBool(), a.describe().constData());
    QVERIFY2(a.errText().contains(QStringLiteral("the last batch was cut short"))
                 || a.errText().contains(QStringLiteral("truncated: its writer never closed it")),
             a.describe().constData());
    // Every transaction but at most the last batch (1,024 frames: 512 transactions) and the one
    // the simulator answered as the poll died.
    const int recovered = o.value(QStringLiteral("ok")).toInt();
    QVERIFY2(answered > 1000, simOut.constData());
    QVERIFY2(recovered <= answered && recovered >= answered - 513,
             qPrintable(QStringLiteral("simulator answered %1, journal holds %2 ok").arg(answered).arg(recovered)));
    // The request in flight, if the journal holds it, is unanswered at the end, not a timeout.
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), o.value(QStringLiteral("ok")).toInt());
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 0);
    QVERIFY(source.value(QStringLiteral("unanswered_at_end")).toInt() <= 1);
}

void TestCliRecord::simulateRecords()
{
    // Every third answer to unit 1 delayed by a fault rule: the journal notes the rule.
    const QString faults = m_dir.filePath(QStringLiteral("faults.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 1, "rules": [{"name": "slow", "kind": "delay", "delay": 5, "probability": 1.0, "units": [1]}]})");
    file.close();
    const QString journal = m_dir.filePath(QStringLiteral("served.mbscope.journal"));
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults, QStringLiteral("--record"), journal},
                       &error),
             qPrintable(error));
    const CliResult ok = runMbscope(QStringList{QStringLiteral("read"), QStringLiteral("--target"), sim.url()} + kSettingsRead);
    QVERIFY2(ok.exitCode == 0, ok.describe().constData());
    const CliResult unknown = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), sim.url(), QStringLiteral("--unit"),
                                          QStringLiteral("9"), QStringLiteral("--address"), QStringLiteral("0x79")});
    QCOMPARE(unknown.exitCode, 1); // exception 0B from the gateway
    QByteArray err;
    sim.stop(&err);
    QCOMPARE(recordedTransactions(err, journal), 2);

    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("exceptions")).toInt(), 1);
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("frames")).toInt(), 4);
    // The delayed answer's fault rule, and each client's endpoints (two reads: two connections).
    QCOMPARE(source.value(QStringLiteral("notes")).toInt(), 3);
    const QJsonObject metadata = source.value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("simulate"));
    QCOMPARE(metadata.value(QStringLiteral("role")).toString(), QStringLiteral("server"));
    QCOMPARE(metadata.value(QStringLiteral("listen")).toArray(), QJsonArray{sim.url()});
    QCOMPARE(metadata.value(QStringLiteral("profile")).toObject().value(QStringLiteral("name")).toString(), QStringLiteral("rosrao-gamma"));

    QList<QByteArray> notes;
    const TrafficJournalRecovery r = TrafficJournalReader::read(journal, {}, [&](const TrafficJournalNote &n) { notes.append(n.json.toByteArray()); });
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(notes.size(), 3);
    QVERIFY2(notes.at(0).startsWith(R"({"endpoints":{"client":"127.0.0.1:)"), notes.at(0).constData());
    QVERIFY2(notes.at(1).contains(R"("faults":["slow"])"), notes.at(1).constData());
    QVERIFY2(notes.at(2).startsWith(R"({"endpoints":{"client":"127.0.0.1:)") && notes.at(2) != notes.at(0), notes.at(2).constData());
}

// Issue 26, item 17: the guide's examples started `simulate &` and used it before it listened.
// --ready-file FILE appears once every endpoint listens, holding their URLs (free ports chosen
// for port 0 included), replaces a file left by an earlier run, and goes when the simulator stops.
void TestCliRecord::simulateReadyFile()
{
    const QString ready = m_dir.filePath(QStringLiteral("sim.ready"));
    {
        QFile stale(ready);
        QVERIFY(stale.open(QIODevice::WriteOnly));
        stale.write("rtu-tcp://127.0.0.1:1\n"); // an earlier run's, killed with SIGKILL
    }
    QProcess sim;
    sim.start(mbscopePath(), {QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--quiet"),
                              QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--listen"),
                              QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--ready-file"), ready});
    QVERIFY2(sim.waitForStarted(30000), qPrintable(sim.errorString()));
    QStringList urls;
    for (int i = 0; i < 600 && sim.state() == QProcess::Running; ++i) { // waits up to a minute on a loaded machine
        QFile file(ready);
        if (file.open(QIODevice::ReadOnly)) {
            const QString text = QString::fromUtf8(file.readAll());
            if (!text.contains(QLatin1String("127.0.0.1:1\n"))) {
                urls = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
                break;
            }
        }
        QThread::msleep(100);
    }
    QVERIFY2(urls.size() == 2, qPrintable(QStringLiteral("ready file: %1; simulate said: %2 %3")
                                             .arg(urls.join(QLatin1Char('|')), QString::fromUtf8(sim.readAllStandardOutput()),
                                                  QString::fromUtf8(sim.readAllStandardError()))));
    QVERIFY2(urls.at(0).startsWith(QLatin1String("rtu-tcp://127.0.0.1:")) && !urls.at(0).endsWith(QLatin1String(":0")), qPrintable(urls.at(0)));
    QVERIFY2(urls.at(1).startsWith(QLatin1String("tcp://127.0.0.1:")) && !urls.at(1).endsWith(QLatin1String(":0")), qPrintable(urls.at(1)));
    // Read at once, with no wait: both answer.
    for (const QString &url : std::as_const(urls)) {
        const CliResult r = runMbscope(QStringList{QStringLiteral("read"), QStringLiteral("--target"), url} + kSettingsRead);
        QVERIFY2(r.exitCode == 0, r.describe().constData());
    }
    ::kill(pid_t(sim.processId()), SIGINT);
    QVERIFY(sim.waitForFinished(30000));
    QCOMPARE(sim.exitCode(), 0);
    QVERIFY2(!QFileInfo::exists(ready), "the ready file outlived the simulator");
}

void TestCliRecord::simulateReadyFileRefused()
{
    // A folder that does not exist: said before any port is bound, exit 2.
    const QString path = m_dir.filePath(QStringLiteral("no-such-folder/sim.ready"));
    const CliResult r = runMbscope({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                                    QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--duration"), QStringLiteral("5s"),
                                    QStringLiteral("--ready-file"), path});
    QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral("--ready-file ") + path + QStringLiteral(": the folder")), r.describe().constData());
    QVERIFY2(!r.outText().contains(QLatin1String("listening")), r.describe().constData());
}

void TestCliRecord::exchangeCommandsRecord()
{
    const QString read = m_dir.filePath(QStringLiteral("read.mbscope.journal"));
    const CliResult r = runMbscope(QStringList{QStringLiteral("read"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--record"), read}
                                   + kSettingsRead);
    QVERIFY2(r.exitCode == 0, r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral("recorded 2 frames (1 transaction) to ") + read), r.describe().constData());
    const QString write = m_dir.filePath(QStringLiteral("write.mbscope.journal"));
    const CliResult w = runMbscope({QStringLiteral("write"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--address"),
                                    QStringLiteral("0x7D"), QStringLiteral("--registers"), QStringLiteral("250,0"), QStringLiteral("--single"),
                                    QStringLiteral("--record"), write});
    QVERIFY2(w.exitCode == 0, w.describe().constData());
    QCOMPARE(recordedTransactions(w.err, write), 2);
    const QString send = m_dir.filePath(QStringLiteral("send.mbscope.journal"));
    const CliResult s = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--hex"),
                                    QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 02"), QStringLiteral("--record"), send});
    QVERIFY2(s.exitCode == 0, s.describe().constData());
    const CliResult a = runMbscope({QStringLiteral("analyze"), send, QStringLiteral("--json")});
    const QJsonObject metadata = a.json().value(QStringLiteral("source")).toObject().value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("send"));
    QCOMPARE(metadata.value(QStringLiteral("requests")).toArray().at(0).toObject().value(QStringLiteral("hex")).toString(),
             QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 02"));
}

void TestCliRecord::runRecordsIntoTheSessionsCapture()
{
    // A plan of one read, its session naming a capture beside it: run --record-capture fills it,
    // a second run refuses to overwrite it, and analyze of the session reads the run.
    const QString session = m_dir.filePath(QStringLiteral("plan.mbscope.json"));
    QFile file(session);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "mbscope-session", "version": 1, "name": "one read",
  "requests": [{"name": "settings", "function": 3, "unit": 1, "address": "0x0079", "quantity": 13}],
  "capture": {"journal": "plan.mbscope.journal"},
  "plan": [{"name": "read the settings", "send": "settings", "expect": {"fields": {"modbus.register_value@0x0079": 1050}}}]})");
    file.close();
    const QStringList run{QStringLiteral("run"), session, QStringLiteral("--target"), m_sim.url(), QStringLiteral("--record-capture")};
    const CliResult first = runMbscope(run);
    QVERIFY2(first.exitCode == 0, first.describe().constData());
    const QString journal = m_dir.filePath(QStringLiteral("plan.mbscope.journal"));
    QCOMPARE(recordedTransactions(first.err, journal), 1);
    const CliResult again = runMbscope(run);
    QCOMPARE(again.exitCode, 2);
    QVERIFY2(again.errText().contains(QStringLiteral("exists: a journal is never overwritten")), again.describe().constData());
    const CliResult a = runMbscope({QStringLiteral("analyze"), session, QStringLiteral("--json")});
    QVERIFY2(a.exitCode == 0, a.describe().constData());
    const QJsonObject metadata = a.json().value(QStringLiteral("source")).toObject().value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("run"));
    QCOMPARE(metadata.value(QStringLiteral("requests")).toArray().at(0).toObject().value(QStringLiteral("name")).toString(),
             QStringLiteral("settings"));
    QCOMPARE(a.json().value(QStringLiteral("count")).toInt(), 1);
}

void TestCliRecord::existingJournalRefused()
{
    const QString path = m_dir.filePath(QStringLiteral("evidence.mbscope.journal"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("keep me");
    file.close();
    const QStringList poll = QStringList{QStringLiteral("poll"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--count"),
                                         QStringLiteral("2"), QStringLiteral("--interval"), QStringLiteral("0"), QStringLiteral("--record"), path}
                             + kSettingsRead;
    const CliResult refused = runMbscope(poll);
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.errText().contains(QStringLiteral("mbscope poll: --record: ")) && refused.errText().contains(QStringLiteral(" exists: a journal is never overwritten"))
                 && refused.errText().contains(QStringLiteral("--force")),
             refused.describe().constData());
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("keep me"));
    file.close();
    const CliResult forced = runMbscope(poll + QStringList{QStringLiteral("--force")});
    QVERIFY2(forced.exitCode == 0, forced.describe().constData());
    QCOMPARE(recordedTransactions(forced.err, path), 2);
    const CliResult noFolder = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--record"),
                                           m_dir.filePath(QStringLiteral("none/x.mbscope.journal"))});
    QCOMPARE(noFolder.exitCode, 2);
    QVERIFY2(noFolder.errText().contains(QStringLiteral("the folder does not exist")), noFolder.describe().constData());
    const CliResult lonelyForce = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--force")});
    QCOMPARE(lonelyForce.exitCode, 2);
    const CliResult log = runMbscope({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--log"), path});
    QCOMPARE(log.exitCode, 2);
    QVERIFY2(log.errText().contains(QStringLiteral("--log was replaced by --record FILE")), log.describe().constData());
}

void TestCliRecord::unreachableTargetLeavesNoJournal()
{
    // Tryout 8, item 2: nothing listens on the port, so nothing was written and nothing answered.
    // The journal used to hold a made-up answer (an empty frame in with the link error, which
    // analyze counted as an answer matching no request), and the file left behind refused the
    // same command run again.
    const QString path = m_dir.filePath(QStringLiteral("p1.mbscope.journal"));
    const QStringList poll{QStringLiteral("poll"), QStringLiteral("--target"), QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(closedPort()),
                           QStringLiteral("--hex"), QStringLiteral("01 03 00 79 00 16 15 DD"), QStringLiteral("--count"),
                           QStringLiteral("2"), QStringLiteral("--record"), path};
    for (int run = 0; run < 2; ++run) {
        const CliResult r = runMbscope(poll);
        QVERIFY2(r.exitCode != 0 && (r.outText() + r.errText()).contains(QStringLiteral("refused")), r.describe().constData());
        QVERIFY2(!r.errText().contains(QStringLiteral(" exists: a journal is never overwritten")), r.describe().constData());
        QVERIFY2(r.errText().contains(QStringLiteral("recorded no frame: removed ") + path), r.describe().constData());
        QVERIFY2(!QFileInfo::exists(path), r.describe().constData());
    }
    // The monitor on a port that is not there: the same.
    const QString bus = m_dir.filePath(QStringLiteral("busx.mbscope.journal"));
    const CliResult m = runMbscope({QStringLiteral("monitor"), QStringLiteral("rtu://%1?baud=9600").arg(m_dir.filePath(QStringLiteral("no-such-tty"))),
                                    QStringLiteral("--record"), bus});
    QCOMPARE(m.exitCode, 2);
    QVERIFY2(m.errText().contains(QStringLiteral("recorded no frame: removed ") + bus), m.describe().constData());
    QVERIFY2(!QFileInfo::exists(bus), m.describe().constData());
}

void TestCliRecord::pollPrintsValuesAndCsv()
{
    const QString csv = m_dir.filePath(QStringLiteral("poll.csv"));
    const CliResult r = runMbscope(QStringList{QStringLiteral("poll"), QStringLiteral("--target"), m_sim.url()} + kSettingsRead
                                   + QStringList{QStringLiteral("--format"), QStringLiteral("u16,hex"), QStringLiteral("--interval"),
                                                 QStringLiteral("10ms"), QStringLiteral("--count"), QStringLiteral("3"), QStringLiteral("--print"),
                                                 QStringLiteral("values"), QStringLiteral("--csv"), csv});
    QVERIFY2(r.exitCode == 0, r.describe().constData());
    // rosrao-gamma's settings block starts 0 1 1 0 (the profile), 22 values per format.
    const QRegularExpression line(QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d{3}  Read Holding Registers 121 x22  ok  [0-9.]+ (ms|µs)  "
                                                 "u16: (\\d+ ){21}\\d+  hex: (\\S+ ){21}\\S+$"),
                                  QRegularExpression::MultilineOption);
    int lines = 0;
    for (auto it = line.globalMatch(r.outText()); it.hasNext(); it.next())
        ++lines;
    QVERIFY2(lines == 3, r.describe().constData());
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = file.readAll().trimmed().split('\n');
    QCOMPARE(rows.size(), 4);
    QCOMPARE(rows.at(0), QByteArray("time,item,status,latency_ms,values_u16,values_hex"));
    const QList<QByteArray> first = rows.at(1).split(',');
    QCOMPARE(first.size(), 6);
    QVERIFY2(first.at(0).endsWith('Z'), rows.at(1).constData());
    QCOMPARE(first.at(1), QByteArray("Read Holding Registers 121 x22"));
    QCOMPARE(first.at(2), QByteArray("ok"));
    QCOMPARE(first.at(4).split(' ').size(), 22);

    const CliResult both = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--print"),
                                       QStringLiteral("values"), QStringLiteral("--json")});
    QCOMPARE(both.exitCode, 2);
    const CliResult what = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--print"), QStringLiteral("everything")});
    QCOMPARE(what.exitCode, 2);
    QVERIFY2(what.errText().contains(QStringLiteral("--print 'everything': expected values")), what.describe().constData());
}

// `mbscope watch --record` (issue 25): the watches of two links, two engines in threads of their
// own, in one journal. Each engine numbers its transactions from 1: the journal keeps each
// link's on a link id of its own and analyze pairs them by link and id (paired by id alone, the
// second link's requests were taken for retries of the first's, their answers unmatched).
void TestCliRecord::watchRecordsEveryLink()
{
    QString why;
    Background second;
    QVERIFY2(second.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                           QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                          &why),
             qPrintable(why));
    const QString session = m_dir.filePath(QStringLiteral("watches.mbscope.json"));
    QFile file(session);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QStringLiteral(R"({"format": "mbscope-session", "version": 2,
  "watches": [{"name": "settings", "target": "%1", "address": 121, "quantity": 22, "intervalMs": 20},
              {"name": "plant", "target": "%2", "address": 0, "quantity": 4, "intervalMs": 20},
              {"name": "pump", "target": "%2", "address": 4, "quantity": 4, "intervalMs": 30}]})")
                   .arg(m_sim.url(), second.url())
                   .toUtf8());
    file.close();
    const QString journal = m_dir.filePath(QStringLiteral("watch.mbscope.journal"));
    const CliResult r = runMbscope({QStringLiteral("watch"), session, QStringLiteral("--count"), QStringLiteral("10"), QStringLiteral("--json"),
                                    QStringLiteral("--record"), journal});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    const QJsonObject summary = QJsonDocument::fromJson(lines.constLast()).object();
    double polls = 0;
    double ok = 0;
    for (const QJsonValue &w : summary.value(QStringLiteral("watches")).toArray()) {
        QVERIFY(w[QLatin1String("polls")].toDouble() >= 10);
        polls += w[QLatin1String("polls")].toDouble();
        ok += w[QLatin1String("ok")].toDouble();
    }
    const int recorded = recordedTransactions(r.err, journal);
    QVERIFY2(recorded >= polls, r.describe().constData());

    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished && a.exitCode == 0, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), recorded);
    // Every poll the watches counted ok is an exchange ok in the journal; a request abandoned
    // when the watches stopped is the journal's too, as a link error.
    QVERIFY2(o.value(QStringLiteral("ok")).toInt() >= ok, a.describe().constData());
    const QJsonArray conversations = o.value(QStringLiteral("conversations")).toArray();
    QCOMPARE(conversations.size(), 2);
    for (const QJsonValue &c : conversations) {
        QVERIFY2(c[QLatin1String("ok")].toInt() >= 10, a.describe().constData());
        QCOMPARE(c[QLatin1String("unmatched_responses")].toInt(), 0);
    }
    const QJsonObject metadata = o.value(QStringLiteral("source")).toObject().value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("watch"));
    QCOMPARE(metadata.value(QStringLiteral("settings")).toObject().value(QStringLiteral("targets")).toArray().size(), 2);

    // Replayed to the first link's device: every request of both links read from the journal
    // and sent.
    const CliResult replay = runMbscope({QStringLiteral("replay"), journal, QStringLiteral("--target"), m_sim.url(), QStringLiteral("--speed"),
                                         QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(replay.finished && (replay.exitCode == 0 || replay.exitCode == 1), replay.describe().constData());
    QCOMPARE(replay.json().value(QStringLiteral("replayed")).toInt(), recorded);
}

// `mbscope scan --record` (issue 25): the scan's probes, one exchange per id asked, in a journal
// that analyze and replay read.
void TestCliRecord::scanRecords()
{
    const QString journal = m_dir.filePath(QStringLiteral("scan.mbscope.journal"));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--units"), QStringLiteral("1-3"),
                                    QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--json"), QStringLiteral("--record"), journal});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QCOMPARE(recordedTransactions(r.err, journal), 3);
    // Exit 1: unit 2 is a gateway target that fails to answer (0B); units 1 and 3 answer.
    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished && a.exitCode == 1, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("conversations")).toArray().size(), 1);
    QVERIFY2(o.value(QStringLiteral("ok")).toInt() >= 1, a.describe().constData()); // unit 1 answers
    const QJsonObject metadata = o.value(QStringLiteral("source")).toObject().value(QStringLiteral("metadata")).toObject();
    QCOMPARE(metadata.value(QStringLiteral("command")).toString(), QStringLiteral("scan"));
    QCOMPARE(metadata.value(QStringLiteral("target")).toString(), m_sim.url());
    const CliResult replay = runMbscope({QStringLiteral("replay"), journal, QStringLiteral("--speed"), QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(replay.finished && (replay.exitCode == 0 || replay.exitCode == 1), replay.describe().constData());
    QCOMPARE(replay.json().value(QStringLiteral("replayed")).toInt(), 3);
    // A usage error leaves no journal behind.
    const QString refused = m_dir.filePath(QStringLiteral("refused.mbscope.journal"));
    const CliResult bad = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--units"), QStringLiteral("9-3"),
                                      QStringLiteral("--record"), refused});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY(!QFile::exists(refused));
}

QTEST_GUILESS_MAIN(TestCliRecord)

#include "tst_cli_record.moc"
