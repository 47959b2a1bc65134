// Replay in the window (ReplayController, ReplayPanel, the Session menu's docks): a recording
// made by the engine polling the built-in simulator (rosrao-gamma over RTU over TCP, traffic
// journaled, a session document naming the journal) is
//  - replayed to the same simulator: no differences;
//  - replayed to one whose profile has 250 at 0x007D changed to 251: the three reads before the
//    recorded write (which puts 250 back) differ by that field, nothing else does;
//  - exported to pcapng by `mbscope export` and analysed offline: the window counts the
//    transactions `mbscope analyze --json` counts, and hands them on through captureAnalysed;
//  - served as a device: a client gets the recorded answer.
// QAbstractItemModelTester watches the differences model; screenshots go to the test output.
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "shell/mainwindow.h"
#include "session/replaycontroller.h"
#include "session/replaydifferencesmodel.h"
#include "session/replaypanel.h"
#include "session/replayserver.h"
#include "shell/sessiontools.h"

#include "exchange/requestitem.h"
#include "traffic/trafficlog.h"
#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "replay/replayrunner.h"
#include "replay/replayscript.h"
#include "transport/linkurl.h"

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QTableView>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 30000;

QByteArray pdu(const char *hex)
{
    return QByteArray::fromHex(hex);
}

// The shipped profile, or a copy with the published 250 at 0x007D (unit 1) made 251.
QString profileFile(const QTemporaryDir &dir, bool changed)
{
    if (!changed)
        return QStringLiteral("rosrao-gamma");
    QFile shipped(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/rosrao-gamma.json"));
    if (!shipped.open(QIODevice::ReadOnly))
        return QString();
    QByteArray profile = shipped.readAll();
    if (!profile.contains("[1050, 0, 0, 0, 250,"))
        return QString();
    profile.replace("[1050, 0, 0, 0, 250,", "[1050, 0, 0, 0, 251,");
    const QString path = dir.filePath(QStringLiteral("changed-rosrao-gamma.json"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(profile) != profile.size())
        return QString();
    return path;
}

} // namespace

class TestReplayController : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void replayToTheTarget_data();
    void replayToTheTarget();
    void replayAsksBeforeSendingWrites();
    void offlineAnalysisCountsAsTheCli();
    void servesTheRecordedAnswers();
    void refusesWithoutWhatItNeeds();
    void sessionMenuShowsTheDock();

private:
    [[nodiscard]] bool record(QString *error);
    [[nodiscard]] bool openRecording(ReplayController &controller);

    QTemporaryDir m_dir;
    EmbeddedSimulator m_sim;
    LinkUrl m_simUrl;
    QString m_journal;
    QString m_session;
    int m_requests = 0;
};

// Reads of the settings of units 1 and 3 (unit 1's three times), a write of the value already
// there, a register the device does not have (exception 02): all answers the profile fixes.
bool TestReplayController::record(QString *error)
{
    const QList<QPair<quint8, QByteArray>> requests = {
        {1, pdu("0300790016")}, {3, pdu("030079000d")}, {1, pdu("0300790016")}, {1, pdu("06007d00fa")},
        {1, pdu("0302000001")}, {1, pdu("0300790016")},
    };
    TrafficLog log;
    if (!log.openJournal(m_journal, {}, true, error))
        return false;
    TransactionEngine engine;
    engine.setTarget(m_simUrl);
    engine.setTrafficLog(&log);
    for (const auto &[unit, request] : requests) {
        RequestItem item = RequestItem::forLink(AduBuilder::rtu(request, unit), m_simUrl);
        item.timeoutMs = 500;
        if (!engine.sendAndWait(item)) {
            *error = QStringLiteral("the engine did not finish a request");
            return false;
        }
        QThread::msleep(10); // a recorded pacing
        ++m_requests;
    }
    engine.closeLink();
    engine.setTrafficLog(nullptr);
    log.closeJournal();
    QFile session(m_session);
    if (!session.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = session.errorString();
        return false;
    }
    session.write(QStringLiteral(R"({"format": "mbscope-session", "version": 1, "name": "recorded",
  "target": {"url": "%1", "timeoutMs": 500}, "capture": {"journal": "recorded.mbscope.journal"}})")
                      .arg(m_simUrl.toString())
                      .toUtf8());
    return true;
}

bool TestReplayController::openRecording(ReplayController &controller)
{
    QSignalSpy opened(&controller, &ReplayController::sourceOpened);
    if (!controller.openSource(m_session))
        return false;
    return opened.wait(kWaitMs) && controller.hasSource();
}

void TestReplayController::initTestCase()
{
    guitest::isolateSettings();
    QVERIFY(m_dir.isValid());
    m_journal = m_dir.filePath(QStringLiteral("recorded.mbscope.journal"));
    m_session = m_dir.filePath(QStringLiteral("recorded.mbscope.json"));
    const EmbeddedSimulator::Started started = m_sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    m_simUrl = started.url;
    QString error;
    QVERIFY2(record(&error), qPrintable(error));
}

void TestReplayController::replayToTheTarget_data()
{
    QTest::addColumn<bool>("changedProfile");
    QTest::addColumn<int>("differences");
    QTest::addColumn<QString>("difference");
    QTest::addColumn<QString>("shot");
    QTest::newRow("identical device") << false << 0 << QString() << QStringLiteral("replay-identical.png");
    // The reads before the recorded write differ by that one field (unit 1's two, unit 3's one:
    // the profile gives both 250 there); the write puts 250 back, so the read after it matches;
    // the write's echo and the exception are the same.
    QTest::newRow("register 0x007D changed") << true << 3 << QStringLiteral("modbus.register_value@0x007D: recorded 250, now 251")
                                             << QStringLiteral("replay-differences.png");
}

void TestReplayController::replayToTheTarget()
{
    QFETCH(bool, changedProfile);
    QFETCH(int, differences);
    QFETCH(QString, difference);
    QFETCH(QString, shot);

    EmbeddedSimulator device;
    const QString profile = profileFile(m_dir, changedProfile);
    QVERIFY(!profile.isEmpty());
    const EmbeddedSimulator::Started started = device.start(profile, QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));

    LinkController link;
    link.connectTo(started.url);
    ReplayController controller(&link);
    QAbstractItemModelTester tester(controller.differences(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    ReplayPanel panel(&controller);
    panel.resize(1100, 420);
    QVERIFY(openRecording(controller));
    QCOMPARE(controller.script()->size(), m_requests);

    QSignalSpy finished(&controller, &ReplayController::replayFinished);
    QSignalSpy replayed(&controller, &ReplayController::transactionsReplayed);
    // The recorded write sent too (the panel asks first: replayAsksBeforeSendingWrites).
    QString error;
    QVERIFY2(controller.startReplay(0, true, &error), qPrintable(error));
    QVERIFY(controller.isReplaying());
    // The GUI thread is free while the replay runs: a refused second start says why at once.
    QVERIFY(!controller.startReplay(0, true, &error));
    QVERIFY2(error.contains(QStringLiteral("already running")), qPrintable(error));
    QVERIFY(finished.wait(kWaitMs));
    QVERIFY(!controller.isReplaying());

    ReplayDifferencesModel *model = controller.differences();
    for (int row = 0; row < model->rowCount(); ++row) {
        QStringList cells;
        for (int column = 0; column < model->columnCount(); ++column)
            cells.append(model->index(row, column).data().toString());
        qInfo("%s", qPrintable(cells.join(QStringLiteral(" | "))));
    }
    QCOMPARE(model->replayed(), m_requests);
    QCOMPARE(replayed.size(), m_requests);
    // A busy machine may slow an answer past the latency rule: that is listed, never asserted.
    const qsizetype slower = model->count(ReplayDifferencesModel::Kind::Latency);
    QCOMPARE(model->differed() - slower, differences);
    QCOMPARE(model->count(ReplayDifferencesModel::Kind::Values), differences);
    QCOMPARE(model->rowCount(), model->differed());
    QVERIFY(controller.lastResult().has_value());
    QCOMPARE(controller.lastResult()->outcomes.size(), m_requests);
    int valueRows = 0;
    for (int row = 0; row < model->rowCount(); ++row) {
        if (model->kindAt(row) != ReplayDifferencesModel::Kind::Values)
            continue;
        ++valueRows;
        QCOMPARE(model->index(row, ReplayDifferencesModel::DifferencesColumn).data().toString(), difference);
        QCOMPARE(model->index(row, ReplayDifferencesModel::KindColumn).data().toString(), QStringLiteral("values"));
        // The recorded and the new answer side by side: the 0x007D register's bytes differ.
        QVERIFY(model->index(row, ReplayDifferencesModel::RecordedColumn).data().toString().contains(QStringLiteral("00 FA")));
        QVERIFY(model->index(row, ReplayDifferencesModel::NowColumn).data().toString().contains(QStringLiteral("00 FB")));
    }
    QCOMPARE(valueRows, differences);
    const QString summary = controller.replaySummary();
    QVERIFY2(summary.contains(QStringLiteral("Answers replayed: %1, differing: %2").arg(m_requests).arg(differences + slower)), qPrintable(summary));
    QVERIFY2(summary.contains(QStringLiteral("latency ms")), qPrintable(summary));

    // Every answer listed, the matching ones too.
    QVERIFY(panel.differencesView()->model() == model);
    model->setShowMatches(true);
    QCOMPARE(model->rowCount(), m_requests);
    model->setShowMatches(false);
    QCOMPARE(model->rowCount(), differences);
    QVERIFY(guitest::saveShot(&panel, shot));
}

// Issue 26 item 1 in the window: the Replay button asks once before a replay whose recording
// holds writes, listing how many to which units and addresses, No by default; No replays the
// rest and lists the write as not sent, Cancel starts nothing, Yes sends it.
void TestReplayController::replayAsksBeforeSendingWrites()
{
    LinkController link;
    link.connectTo(m_simUrl);
    ReplayController controller(&link);
    ReplayPanel panel(&controller);
    QVERIFY(openRecording(controller));
    QString question;
    QString details;
    bool noByDefault = false;
    QMessageBox::StandardButton answer = QMessageBox::Cancel;
    int asked = 0;
    panel.setWritesAsker([&](QMessageBox &box) {
        ++asked;
        question = box.text();
        details = box.informativeText();
        noByDefault = box.defaultButton() == box.button(QMessageBox::No);
        return answer;
    });

    panel.replay();
    QCOMPARE(asked, 1);
    QVERIFY(!controller.isReplaying());
    QCOMPARE(question, QStringLiteral("The recording holds 1 write(s) to the device: unit 1 at 0x007D."));
    QVERIFY2(details.contains(QStringLiteral("changes the device")), qPrintable(details));
    QVERIFY(noByDefault);

    answer = QMessageBox::No;
    QSignalSpy finished(&controller, &ReplayController::replayFinished);
    panel.replay();
    QCOMPARE(asked, 2);
    QVERIFY(controller.isReplaying());
    QVERIFY(finished.wait(kWaitMs));
    QVERIFY(controller.lastResult().has_value());
    QCOMPARE(controller.lastResult()->skippedWrites.size(), 1);
    QCOMPARE(controller.lastResult()->outcomes.size(), m_requests - 1);
    QVERIFY2(controller.replaySummary().contains(QStringLiteral("Writes not sent: 1 (unit 1 at 0x007D).")), qPrintable(controller.replaySummary()));

    answer = QMessageBox::Yes;
    if (!link.isConnected()) // the replay closed the link's own connection
        link.connectTo(m_simUrl);
    panel.replay();
    QVERIFY(finished.wait(kWaitMs));
    QCOMPARE(asked, 3);
    QCOMPARE(controller.lastResult()->skippedWrites.size(), 0);
    QCOMPARE(controller.lastResult()->outcomes.size(), m_requests);
}

void TestReplayController::offlineAnalysisCountsAsTheCli()
{
#ifndef MBSCOPE_BINARY
    QSKIP("built without the mbscope executable: nothing to compare mbscope analyze with");
#else
    // The recording as a pcapng, written by the CLI (RTU frames on the simulator's port).
    const QString pcap = m_dir.filePath(QStringLiteral("recorded.pcapng"));
    QProcess exporter;
    exporter.start(QStringLiteral(MBSCOPE_BINARY), {QStringLiteral("export"), m_journal, QStringLiteral("--pcap"), pcap});
    QVERIFY(exporter.waitForFinished(kWaitMs));
    QVERIFY2(exporter.exitCode() == 0, exporter.readAllStandardError().constData());
    const QString port = QString::number(m_simUrl.port);
    QProcess analyze;
    analyze.start(QStringLiteral(MBSCOPE_BINARY),
                  {QStringLiteral("analyze"), pcap, QStringLiteral("--rtu-port"), port, QStringLiteral("--json")});
    QVERIFY(analyze.waitForFinished(kWaitMs));
    const QJsonObject cli = QJsonDocument::fromJson(analyze.readAllStandardOutput()).object();
    const int cliCount = cli.value(QStringLiteral("count")).toInt(-1);
    QCOMPARE(cliCount, m_requests);

    LinkController link;
    ReplayController controller(&link);
    ReplayPanel panel(&controller);
    panel.resize(1100, 300);
    QSignalSpy analysed(&controller, &ReplayController::captureAnalysed);
    QSignalSpy failed(&controller, &ReplayController::sourceFailed);
    // Without the RTU port nothing in it is Modbus: the panel says which setting chooses it.
    QVERIFY(panel.open(pcap));
    QVERIFY(analysed.wait(kWaitMs));
    QCOMPARE(analysed.takeFirst().at(1).value<QList<Transaction>>().size(), 0);
    QVERIFY2(controller.sourceSummary().contains(QStringLiteral("RTU ports")), qPrintable(controller.sourceSummary()));

    CaptureOptions options;
    options.rtuPorts = {quint16(m_simUrl.port)};
    controller.setCaptureOptions(options);
    QVERIFY(controller.openSource(pcap));
    QVERIFY(analysed.wait(kWaitMs));
    QVERIFY(failed.isEmpty());
    const QList<QVariant> arguments = analysed.takeFirst();
    QCOMPARE(arguments.at(0).toString(), QStringLiteral("recorded.pcapng"));
    const auto transactions = arguments.at(1).value<QList<Transaction>>();
    QCOMPARE(transactions.size(), cliCount);
    QCOMPARE(controller.transactionCount(), cliCount);
    QCOMPARE(controller.sourceStatistics().count(), quint64(cli.value(QStringLiteral("count")).toInt()));
    QCOMPARE(controller.sourceStatistics().ok(), quint64(cli.value(QStringLiteral("ok")).toInt()));
    QCOMPARE(controller.sourceStatistics().exceptions(), quint64(cli.value(QStringLiteral("exceptions")).toInt()));
    QVERIFY2(controller.sourceSummary().contains(QStringLiteral("transactions %1, ok %2").arg(cliCount).arg(controller.sourceStatistics().ok())), qPrintable(controller.sourceSummary()));
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("replay-offline.png")));
#endif
}

void TestReplayController::servesTheRecordedAnswers()
{
    LinkController link;
    ReplayController controller(&link);
    QVERIFY(openRecording(controller));
    QString error;
    QVERIFY2(controller.startServing(QStringLiteral("tcp://127.0.0.1:0"), ReplayResponder::Unrecorded::Exception0B, 0, &error),
             qPrintable(error));
    const LinkUrl served = controller.server()->boundUrl();
    QVERIFY(served.port != 0);

    // The RTU-over-TCP recording answers over Modbus TCP: re-framed, matched by unit and PDU.
    const ReplayExchange &first = controller.script()->exchanges().front();
    TransactionEngine engine;
    engine.setTarget(served);
    const std::optional<Transaction> answer = engine.sendAndWait(
        RequestItem::forLink(ReplayRunner::wireBytes(*controller.script(), 0, served.framing()), served));
    QVERIFY(answer.has_value());
    QCOMPARE(answer->status, TransactionStatus::Ok);
    QCOMPARE(AduBuilder::parse(answer->response, Framing::Tcp).pdu, AduBuilder::parse(first.recorded.response, first.framing).pdu);
    // A request never recorded: exception 0B.
    AduOptions mbap;
    mbap.framing = Framing::Tcp;
    mbap.transactionId = 9;
    const std::optional<Transaction> unrecorded =
        engine.sendAndWait(RequestItem::forLink(AduBuilder::complete(pdu("0300800001"), mbap), served));
    QVERIFY(unrecorded.has_value());
    QCOMPARE(unrecorded->status, TransactionStatus::Exception);
    QCOMPARE(unrecorded->exceptionCode, quint8(0x0B));
    engine.closeLink();

    const ReplayResponder::Counters counters = controller.server()->counters();
    QCOMPARE(counters.served, quint64(1));
    QCOMPARE(counters.unrecorded, quint64(1));
    QVERIFY2(controller.servingText().contains(QStringLiteral("Answers served: 1, silences kept: 0, requests never recorded: 1.")), qPrintable(controller.servingText()));
    controller.stopServing();
    QVERIFY(!controller.server()->isServing());
}

void TestReplayController::refusesWithoutWhatItNeeds()
{
    LinkController link;
    ReplayController controller(&link);
    QString error;
    QVERIFY(!controller.startReplay(1, false, &error));
    QVERIFY2(error.contains(QStringLiteral("Open a capture")), qPrintable(error));
    QVERIFY(openRecording(controller));
    QVERIFY(!controller.startReplay(1, false, &error));
    QVERIFY2(error.contains(QStringLiteral("Connect to the device")), qPrintable(error));

    QSignalSpy failed(&controller, &ReplayController::sourceFailed);
    QVERIFY(!controller.openSource(m_dir.filePath(QStringLiteral("missing.pcapng"))));
    QCOMPARE(failed.size(), 1);
    QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("no such file")), qPrintable(failed.at(0).at(0).toString()));
    QVERIFY(!controller.startServing(QStringLiteral("tcp://127.0.0.1:99999"), ReplayResponder::Unrecorded::Ignore, 1, &error));
    QVERIFY2(error.contains(QStringLiteral("99999")), qPrintable(error));
}

void TestReplayController::sessionMenuShowsTheDock()
{
    MainWindow window;
    window.resize(1280, 860);
    SessionTools *tools = window.findChild<SessionTools *>();
    QVERIFY(tools);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy opened(tools->replay(), &ReplayController::sourceOpened);
    QVERIFY(tools->replayPanel()->open(m_session));
    QVERIFY(opened.wait(kWaitMs));
    tools->replayDock()->raise();
    QCoreApplication::processEvents();
    QVERIFY(tools->replayDock()->isVisible());
    QVERIFY(guitest::saveShot(&window, QStringLiteral("replay-window.png")));
}

QTEST_MAIN(TestReplayController)
#include "tst_replaycontroller.moc"
