// The window records, always: a connection's frames reach a journal in the capture folder as they
// happen, Save puts the journal beside the session and names it in the document, the Preferences
// turn it off or change its policy, and a journal a crash left behind is offered back at the next
// start with what came back. The watches and scans of the window go into the same journal and the
// traffic list, each link's engine a link of the journal of its own (issue 25).
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "session/replaycontroller.h"
#include "session/sessioncontroller.h"
#include "shell/sessiontools.h"
#include "shell/mainwindow.h"
#include "sim/embeddedsimulator.h"
#include "common/noticebanner.h"
#include "discovery/scandialog.h"
#include "traffic/trafficmonitor.h"
#include "traffic/trafficmodel.h"
#include "watch/watchworkspace.h"
#include "session/recordingcontrol.h"
#include "session/recordingsettings.h"

#include "fleet/watchrunner.h"
#include "session/sessionreader.h"
#include "traffic/capturedirectory.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QSettings>
#include <QtCore/QSysInfo>
#include <QtCore/QTemporaryDir>
#include <QtWidgets/QSpinBox>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

#include <csignal>

using namespace mbscope;

class TestRecording : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void init();
    void connectionIsJournaled();
    void turnedOffRecordsNothing();
    void saveKeepsTheJournalBesideTheSession();
    void crashLeftJournalIsOffered();
    void signalsCloseTheJournal_data();
    void signalsCloseTheJournal();
    void watchesAndScansAreRecordedAndListed();
    void stoppingOnItsOwnIsSaid();

private:
    QTemporaryDir m_captures;
};

namespace {

const QByteArray kRead = QByteArray::fromHex("01030079001615DD");

LinkUrl startSimulator(EmbeddedSimulator &sim)
{
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    if (!started.ok)
        qWarning("%s", qPrintable(started.error));
    return started.url;
}

struct JournalCount {
    quint64 out = 0;
    quint64 ok = 0;
    TrafficJournalRecovery recovery;
};

JournalCount countJournal(const QString &path)
{
    JournalCount c;
    c.recovery = TrafficJournalReader::read(path, [&c](const TrafficEntry &e) {
        c.out += e.direction == TrafficDirection::Out ? 1 : 0;
        c.ok += e.verdict == TrafficVerdict::Ok ? 1 : 0;
    });
    return c;
}

} // namespace

void TestRecording::init()
{
    QVERIFY(m_captures.isValid());
    QDir(m_captures.path()).removeRecursively();
    QDir().mkpath(m_captures.path());
    RecordingSettings settings;
    settings.folder = m_captures.path();
    settings.store();
}

void TestRecording::connectionIsJournaled()
{
    EmbeddedSimulator sim;
    const LinkUrl url = startSimulator(sim);
    LinkController controller;
    const RecordingSettings settings = RecordingSettings::load();
    controller.setRecording(true, settings.directory(), settings.policy());
    QSignalSpy recording(&controller, &LinkController::recordingChanged);
    QSignalSpy latest(&controller, &LinkController::latestTransaction);
    controller.connectTo(url);
    QCOMPARE(recording.count(), 1);
    const QString path = controller.recordingPath();
    QVERIFY2(path.startsWith(m_captures.path()), qPrintable(path));
    QVERIFY(QFileInfo(path).fileName().contains(QStringLiteral("rtu-tcp_127.0.0.1_")));
    QVERIFY(QFile::exists(path + QStringLiteral(".open")));
    for (int i = 0; i < 3; ++i) {
        QVERIFY(controller.send(kRead) > 0);
        QVERIFY(latest.wait(5000));
    }
    controller.disconnectLink();
    QVERIFY(controller.recordingPath().isEmpty());
    QVERIFY(!QFile::exists(path + QStringLiteral(".open")));
    const JournalCount c = countJournal(path);
    QVERIFY2(c.recovery.isClean(), qPrintable(c.recovery.message));
    QCOMPARE(c.out, quint64(3));
    QCOMPARE(c.ok, quint64(3));
    QCOMPARE(c.recovery.links, QStringList{url.toString()});
}

void TestRecording::turnedOffRecordsNothing()
{
    EmbeddedSimulator sim;
    const LinkUrl url = startSimulator(sim);
    LinkController controller;
    const RecordingSettings settings = RecordingSettings::load();
    controller.setRecording(false, settings.directory(), settings.policy());
    QSignalSpy latest(&controller, &LinkController::latestTransaction);
    controller.connectTo(url);
    QVERIFY(controller.send(kRead) > 0);
    QVERIFY(latest.wait(5000));
    QVERIFY(controller.recordingPath().isEmpty());
    controller.disconnectLink();
    QVERIFY(CaptureDirectory(m_captures.path()).journals().isEmpty());
}

void TestRecording::saveKeepsTheJournalBesideTheSession()
{
    QTemporaryDir sessions;
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    LinkController *link = window.controller();
    QSignalSpy latest(link, &LinkController::latestTransaction);
    QVERIFY(link->send(kRead) > 0);
    QVERIFY(latest.wait(5000));
    const QString sessionPath = sessions.filePath(QStringLiteral("bench.mbscope.json"));
    QVERIFY(window.session()->saveAs(sessionPath));
    const QString journal = link->recordingPath();
    QCOMPARE(QFileInfo(journal).absolutePath(), QFileInfo(sessionPath).absolutePath());
    QVERIFY2(QFileInfo(journal).fileName().startsWith(QStringLiteral("bench-")), qPrintable(journal));
    // The document names it, and nothing is left in the capture folder.
    const SessionLoadResult read = SessionReader::load(sessionPath);
    QVERIFY(read.document);
    QVERIFY(read.document->capture);
    QCOMPARE(read.document->capture->journal, QFileInfo(journal).fileName());
    QVERIFY(CaptureDirectory(m_captures.path()).journals().isEmpty());
    QVERIFY(!window.session()->isModified());
    // Recording goes on into it; a second Save keeps it.
    QVERIFY(link->send(kRead) > 0);
    QVERIFY(latest.wait(5000));
    QVERIFY(window.session()->save());
    QCOMPARE(link->recordingPath(), journal);
    link->disconnectLink();
    const JournalCount c = countJournal(journal);
    QVERIFY2(c.recovery.isClean(), qPrintable(c.recovery.message));
    QCOMPARE(c.out, quint64(2));
    // The session's capture opens as a capture (what File > Open capture and replay read).
    ReplayController *replay = window.sessionTools()->replay();
    QSignalSpy opened(replay, &ReplayController::sourceOpened);
    QVERIFY(replay->openSource(sessionPath));
    QVERIFY(opened.wait(10000));
}

void TestRecording::crashLeftJournalIsOffered()
{
    // A journal whose writer died: two requests and their answers, a marker naming a process
    // that has ended, and a last batch cut short.
    const QString path = CaptureDirectory(m_captures.path()).newJournalPath(QDateTime::currentDateTime().addSecs(-60),
                                                                          QStringLiteral("tcp://127.0.0.1:502"));
    {
        TrafficJournalWriter writer;
        QString error;
        QVERIFY2(writer.open(path, {}, false, &error), qPrintable(error));
        writer.addLink(0, u"tcp://127.0.0.1:502");
        const QByteArray request = QByteArray::fromHex("000100000006010300000001");
        const QByteArray answer = QByteArray::fromHex("00010000000501030200FF");
        for (quint64 i = 0; i < 2; ++i) {
            writer.addFrame(TrafficEntry{2 * i, 1000 + qint64(i), i + 1, 0, TrafficDirection::Out, TrafficVerdict::Sent, request});
            writer.addFrame(TrafficEntry{2 * i + 1, 2000 + qint64(i), i + 1, 0, TrafficDirection::In, TrafficVerdict::Ok, answer});
        }
        writer.close();
    }
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::Append));
        f.write("BTCH\x10\x00"); // a batch cut short by the kill
    }
    QFile marker(path + QStringLiteral(".open"));
    QVERIFY(marker.open(QIODevice::WriteOnly));
    marker.write("999999\n" + QSysInfo::machineHostName().toUtf8() + '\n');
    marker.close();

    MainWindow window;
    NoticeBanner *banner = window.recording()->recoveryBanner();
    QVERIFY(!banner->isHidden());
    QVERIFY2(banner->text().contains(QStringLiteral("2 requests came back, 4 frames")), qPrintable(banner->text()));
    QVERIFY2(banner->text().contains(QStringLiteral("cut short")), qPrintable(banner->text()));
    // Opening it puts it in the traffic list, and it is offered no more.
    QSignalSpy opened(window.sessionTools()->replay(), &ReplayController::sourceOpened);
    Q_EMIT banner->linkActivated(QStringLiteral("open"));
    QVERIFY(opened.wait(10000));
    QVERIFY(banner->isHidden());
    QVERIFY(!QFile::exists(marker.fileName()));
    QVERIFY(CaptureDirectory(m_captures.path()).abandoned().isEmpty());
    MainWindow again;
    QVERIFY(again.recording()->recoveryBanner()->isHidden());
}

void TestRecording::signalsCloseTheJournal_data()
{
    QTest::addColumn<int>("signal");
    QTest::newRow("SIGTERM") << int(SIGTERM);
    QTest::newRow("SIGINT") << int(SIGINT);
}

// Issue 26 item 8: the window ended by SIGTERM (or Ctrl-C in its terminal) left its journal open,
// and the next start showed a recovery banner for a journal nothing had cut. The mbscope binary as
// a user starts it (first run: its simulator, connected, recording), the signal sent once the
// journal is being written: the window exits 0, the journal's marker is gone, nothing is offered
// for recovery, and the journal reads to its end.
void TestRecording::signalsCloseTheJournal()
{
#ifndef MBSCOPE_BINARY
    QSKIP("built without the mbscope binary");
#else
    QFETCH(int, signal);
    QTemporaryDir home;
    QVERIFY(home.isValid());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("HOME"), home.path());
    for (const char *name : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"}) {
        const QString path = home.filePath(QString::fromLatin1(name).toLower());
        QVERIFY(QDir().mkpath(path));
        env.insert(QString::fromLatin1(name), path);
    }
    const QString captures = home.filePath(QStringLiteral("xdg_data_home/mbscope/mbscope/captures"));
    QProcess mbscope;
    mbscope.setProcessEnvironment(env);
    mbscope.start(QStringLiteral(MBSCOPE_BINARY), {});
    QVERIFY2(mbscope.waitForStarted(30000), qPrintable(mbscope.errorString()));
    const auto markers = [&captures] {
        return QDir(captures).entryList({QStringLiteral("*.mbscope.journal.open")}, QDir::Files);
    };
    QTRY_VERIFY_WITH_TIMEOUT(!markers().isEmpty(), 30000);
    QTest::qWait(1000); // most likely the first run's ready request and answer in it too
    ::kill(pid_t(mbscope.processId()), signal);
    QVERIFY(mbscope.waitForFinished(30000));
    const QByteArray err = mbscope.readAllStandardError();
    QCOMPARE(mbscope.exitStatus(), QProcess::NormalExit);
    QVERIFY2(mbscope.exitCode() == 0, err.constData());
    QVERIFY2(markers().isEmpty(), qPrintable(markers().join(QLatin1Char(' '))));
    QVERIFY(CaptureDirectory(captures).abandoned().isEmpty());
    const QList<CaptureDirectory::Journal> journals = CaptureDirectory(captures).journals();
    QCOMPARE(journals.size(), 1);
    const TrafficJournalRecovery read = TrafficJournalReader::read(journals.constFirst().path, [](const TrafficEntry &) {});
    QVERIFY2(read.isClean(), qPrintable(read.message));
#endif
}

// The watches poll the composer's device on engines of their own, and a unit scan asks it: their
// frames reach the traffic list and the connection's journal (they reached neither), each engine
// on a link of the journal of its own, since each numbers its transactions from 1.
void TestRecording::watchesAndScansAreRecordedAndListed()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    LinkController *link = window.controller();
    const QString url = link->url().toString();
    const QString journal = link->recordingPath();
    QVERIFY(!journal.isEmpty());
    TrafficModel *traffic = window.trafficMonitor()->model();
    const int before = traffic->rowCount();

    WatchDefinition watch;
    watch.name = QStringLiteral("settings");
    watch.target = url;
    watch.unit = 1;
    watch.address = 0x79;
    watch.quantity = 22;
    watch.intervalMs = 20;
    WatchWorkspace *workspace = window.watchWorkspace();
    workspace->addWatch(watch);
    workspace->startAll();
    QTRY_VERIFY_WITH_TIMEOUT(workspace->runner()->counters(0).ok >= 5, 10000);
    workspace->stopAll();
    QTRY_VERIFY_WITH_TIMEOUT(traffic->rowCount() >= before + 10, 5000);

    ScanDialog *scan = window.scanDialog();
    scan->setTarget(link->url());
    scan->findChild<QSpinBox *>(QStringLiteral("scanFirstUnit"))->setValue(1);
    scan->findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(3);
    QSignalSpy finished(scan, &ScanDialog::scanFinished);
    const int beforeScan = traffic->rowCount();
    scan->start();
    QVERIFY(finished.wait(20000));
    QTRY_VERIFY_WITH_TIMEOUT(traffic->rowCount() >= beforeScan + 6, 5000); // 3 ids asked, each a request and an outcome

    link->disconnectLink();
    const JournalCount c = countJournal(journal);
    QVERIFY2(c.recovery.isClean(), qPrintable(c.recovery.message));
    QVERIFY2(c.out >= 5 + 3, qPrintable(QString::number(c.out)));
    // The composer's link, the watch's and the scan's: three links named by the one URL.
    QCOMPARE(c.recovery.links.count(url), 3);
}


void TestRecording::stoppingOnItsOwnIsSaid()
{
    // A recording whose next part cannot be made (its folder was removed under it) stops: the
    // window says so at once, in a notice that stays, instead of recording nothing unseen.
    EmbeddedSimulator sim;
    const LinkUrl url = startSimulator(sim);
    MainWindow window;
    QTemporaryDir captures;
    const QString folder = captures.filePath(QStringLiteral("captures"));
    QVERIFY(QDir().mkpath(folder));
    RollingCapture::Policy policy;
    policy.rotateBytes = 2048; // a part every few exchanges
    window.controller()->setRecording(true, CaptureDirectory(folder), policy);
    QSignalSpy recording(window.controller(), &LinkController::recordingChanged);
    QSignalSpy latest(window.controller(), &LinkController::latestTransaction);
    window.controller()->connectTo(url);
    const QString first = window.controller()->recordingPath();
    QVERIFY(!first.isEmpty());
    QVERIFY(window.controller()->send(kRead) > 0);
    QVERIFY(latest.wait(5000));
    QVERIFY(QDir(folder).removeRecursively());
    for (int i = 0; i < 60 && recording.count() < 2; ++i) {
        QVERIFY(window.controller()->send(kRead) > 0);
        QVERIFY(latest.wait(5000));
        QCoreApplication::processEvents();
    }
    QTRY_COMPARE_WITH_TIMEOUT(recording.count(), 2, 5000);
    const QString problem = recording.last().at(1).toString();
    QVERIFY2(problem.startsWith(QStringLiteral("the recording stopped: ")), qPrintable(problem));
    QVERIFY2(problem.contains(QStringLiteral("No such file or directory")), qPrintable(problem));
    QCOMPARE(window.controller()->recordingProblem(), problem);
    NoticeBanner *banner = window.recording()->recoveryBanner();
    QVERIFY(!banner->isHidden());
    QVERIFY2(banner->text().contains(QStringLiteral("Not recording any more")), qPrintable(banner->text()));
    QVERIFY2(banner->text().contains(QStringLiteral("No such file or directory")), qPrintable(banner->text()));
    // Said once, however many frames come after.
    for (int i = 0; i < 5; ++i) {
        QVERIFY(window.controller()->send(kRead) > 0);
        QVERIFY(latest.wait(5000));
    }
    QCoreApplication::processEvents();
    QCOMPARE(recording.count(), 2);
    Q_EMIT banner->dismissed();
    QVERIFY(banner->isHidden());
    window.controller()->disconnectLink();
}

QTEST_MAIN(TestRecording)
#include "tst_recording.moc"
