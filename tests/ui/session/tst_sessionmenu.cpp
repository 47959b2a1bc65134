// The window's session file: saved from one window and opened in another gives the same target and
// requests; a broken file is refused with its problems and changes nothing; the modified flag and
// the title follow edits; the unsaved-changes prompt is answered without a modal dialog.
#include "link/connectionbar.h"
#include "link/tapfields.h"
#include "guitestsupport.h"
#include "shell/mainwindow.h"
#include "shell/windowlayout.h"
#include "compose/rawrequesteditor.h"
#include "compose/requestcomposer.h"
#include "compose/savedrequests.h"
#include "session/sessioncontroller.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "watch/watchworkspace.h"

#include "session/sessionreader.h"
#include "transport/linkurl.h"

#include <QtCore/QFile>
#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QStatusBar>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

const QString kRequest = QStringLiteral("01 03 00 79 00 16 15 DD");

void setTarget(MainWindow &window, const QString &url)
{
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    QVERIFY2(parsed.url, qPrintable(parsed.error));
    window.connectionBar()->setUrl(*parsed.url);
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace

class TestSessionMenu : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void init() { SavedRequests::store({{QStringLiteral("bench read"), QStringLiteral("01 04 00 00 00 02 71 CB")}}); }
    void savedSessionReopensTheSame();
    void brokenFileChangesNothing_data();
    void brokenFileChangesNothing();
    void modifiedFlagAndTitle();
    void promptAnswersDecideNewAndClose_data();
    void promptAnswersDecideNewAndClose();
    void recentFilesKeepTheLastEight();
    void savingKeepsWhatTheWindowDoesNotShow();
    void layoutIsRestored();
    void layoutIsRememberedPerScreenSize_data();
    void layoutIsRememberedPerScreenSize();
    void versionOneSavedSaysUpgraded();
    void watchesKeptWhenSaved();
    void tapKeptWhenSaved();
    void trafficNamesTheConnectedLink();
    void quitAfterFirstRunAsksNothing();
};

void TestSessionMenu::savedSessionReopensTheSame()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bench.mbscope.json"));

    // A request named while the session is open is the session's; those the list held before
    // (built-in presets, other sessions' requests) are not written into it (issue 14, item 9).
    SavedRequests::store({});
    MainWindow first;
    SavedRequests::store({{QStringLiteral("bench read"), QStringLiteral("01 04 00 00 00 02 71 CB")}});
    first.composer()->rawEditor()->reloadSavedRequests();
    setTarget(first, QStringLiteral("rtu-tcp://127.0.0.1:4001?timeout=750ms"));
    first.composer()->setRequestText(kRequest);
    first.composer()->intervalSpin()->setValue(250);
    first.composer()->countSpin()->setValue(40);
    QVERIFY(first.session()->isModified());
    QVERIFY(first.session()->saveAs(path));
    QVERIFY(!first.session()->isModified());
    const SessionDocument saved = first.session()->currentDocument();
    QCOMPARE(saved.target.url, QStringLiteral("rtu-tcp://127.0.0.1:4001?timeout=750ms"));
    QStringList names;
    for (const SessionRequest &r : saved.requests)
        names << r.name;
    QVERIFY2(saved.request(QStringLiteral("bench read")), qPrintable(names.join(u',')));

    // Another list of named requests in the settings: opening the session brings its ones back.
    SavedRequests::store({{QStringLiteral("other"), QStringLiteral("01 01 00 00 00 08 3D CC")}});
    MainWindow second;
    QVERIFY(second.session()->currentDocument() != saved);
    QVERIFY(second.session()->open(path));
    const SessionDocument reopened = second.session()->currentDocument();
    QCOMPARE(reopened.target, saved.target);
    QCOMPARE(reopened.poll, saved.poll);
    for (const SessionRequest &request : saved.requests) {
        QVERIFY2(reopened.request(request.name), qPrintable(request.name));
        QCOMPARE(*reopened.request(request.name), request);
    }
    QVERIFY(!second.session()->isModified());
    QCOMPARE(second.connectionBar()->url()->toString(), QStringLiteral("rtu-tcp://127.0.0.1:4001?timeout=750ms"));
    QCOMPARE(second.connectionBar()->timeoutMs(), 750);
    QCOMPARE(second.composer()->rawEditor()->text().trimmed(), kRequest);
    QCOMPARE(second.composer()->intervalSpin()->value(), 250);
    QCOMPARE(second.composer()->countSpin()->value(), 40);
    QVERIFY(second.composer()->rawEditor()->loadSaved(QStringLiteral("bench read")));
    QVERIFY(second.composer()->rawEditor()->loadSaved(QStringLiteral("other"))); // kept, not replaced
    QVERIFY(second.session()->recentFiles().contains(second.session()->filePath()));
}

void TestSessionMenu::brokenFileChangesNothing_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("problem"); // a part of the reported problems

    QTest::newRow("syntax") << QByteArray("{\"format\": \"mbscope-session\", \"version\": 1,,}") << QStringLiteral("line 1");
    QTest::newRow("bad hex") << QByteArray(R"({"format": "mbscope-session", "version": 1,
        "requests": [{"name": "composer", "hex": "01 0Z"}]})") << QStringLiteral("requests[0].hex");
    QTest::newRow("bad url") << QByteArray(R"({"format": "mbscope-session", "version": 1,
        "target": {"url": "nope://x"}, "requests": [{"name": "composer", "hex": "01 03 00 00 00 01 84 0A"}]})")
                             << QStringLiteral("target.url");
    QTest::newRow("unknown key") << QByteArray(R"({"format": "mbscope-session", "version": 1, "targets": {}})")
                                 << QStringLiteral("targets");
}

void TestSessionMenu::brokenFileChangesNothing()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.mbscope.json"));
    QVERIFY(writeFile(path, json));

    MainWindow window;
    setTarget(window, QStringLiteral("tcp://127.0.0.1:1502"));
    window.composer()->setRequestText(kRequest);
    QStringList reported;
    window.session()->setProblemReport([&reported](const QString &, const QStringList &problems) { reported = problems; });
    const SessionDocument before = window.session()->currentDocument();
    const QString titleBefore = window.windowTitle();

    QVERIFY(!window.session()->open(path));
    QVERIFY(!reported.isEmpty());
    QVERIFY2(reported.join(QLatin1Char('\n')).contains(problem), qPrintable(reported.join(QLatin1Char('\n'))));
    QCOMPARE(window.session()->lastProblems(), reported);
    QCOMPARE(window.session()->currentDocument(), before);
    QCOMPARE(window.session()->filePath(), QString());
    QCOMPARE(window.windowTitle(), titleBefore);
    QVERIFY(!window.session()->recentFiles().contains(path));
}

void TestSessionMenu::modifiedFlagAndTitle()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.mbscope.json"));
    MainWindow window;
    QCOMPARE(window.windowTitle(), QStringLiteral("mbscope"));
    QVERIFY(!window.session()->isModified());

    window.composer()->intervalSpin()->setValue(1234);
    QVERIFY(window.session()->isModified() == false); // no request: the poll is not part of the session
    window.composer()->setRequestText(kRequest);
    QVERIFY(window.session()->isModified());
    QVERIFY(window.windowTitle().contains(QLatin1Char('*')));

    QVERIFY(window.session()->saveAs(path));
    QCOMPARE(window.windowTitle(), QStringLiteral("lab.mbscope.json — mbscope"));
    setTarget(window, QStringLiteral("tcp://127.0.0.1:1502"));
    QCOMPARE(window.windowTitle(), QStringLiteral("lab.mbscope.json* — mbscope"));
    // Back to what was saved: not modified any more.
    window.session()->open(path);
    QCOMPARE(window.windowTitle(), QStringLiteral("lab.mbscope.json — mbscope"));
    window.composer()->countSpin()->setValue(5);
    QVERIFY(window.session()->isModified());
    QVERIFY(window.session()->save());
    QVERIFY(!window.session()->isModified());
    QVERIFY(guitest::saveShot(&window, QStringLiteral("sessionmenu-saved.png")));
}

void TestSessionMenu::promptAnswersDecideNewAndClose_data()
{
    QTest::addColumn<int>("answer");
    QTest::addColumn<bool>("goesOn");
    QTest::addColumn<bool>("fileHasEdit");
    QTest::newRow("save") << int(SessionController::Choice::Save) << true << true;
    QTest::newRow("discard") << int(SessionController::Choice::Discard) << true << false;
    QTest::newRow("cancel") << int(SessionController::Choice::Cancel) << false << false;
}

void TestSessionMenu::promptAnswersDecideNewAndClose()
{
    QFETCH(int, answer);
    QFETCH(bool, goesOn);
    QFETCH(bool, fileHasEdit);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("prompt.mbscope.json"));

    for (const bool viaClose : {false, true}) {
        MainWindow window;
        window.composer()->setRequestText(kRequest);
        QVERIFY(window.session()->saveAs(path));
        window.composer()->countSpin()->setValue(7);
        QVERIFY(window.session()->isModified());
        int asked = 0;
        window.session()->setChangesPrompt([&asked, answer](const QString &fileName) {
            ++asked;
            [&] { QCOMPARE(fileName, QStringLiteral("prompt.mbscope.json")); }();
            return SessionController::Choice(answer);
        });
        window.show();
        const bool wentOn = viaClose ? window.close() : window.session()->newSession();
        QCOMPARE(asked, 1);
        QCOMPARE(wentOn, goesOn);
        QCOMPARE(window.isVisible(), !(viaClose && goesOn));
        if (!viaClose)
            QCOMPARE(window.composer()->countSpin()->value(), goesOn ? 0 : 7);
        const SessionLoadResult onDisk = [&] {
            QFile file(path);
            if (!file.open(QIODevice::ReadOnly))
                return SessionLoadResult{};
            return SessionReader::parse(file.readAll(), path);
        }();
        QVERIFY(onDisk.ok());
        QCOMPARE(onDisk.document->poll.has_value(), fileHasEdit);
        QVERIFY(QFile::remove(path));
    }
}

void TestSessionMenu::recentFilesKeepTheLastEight()
{
    QTemporaryDir dir;
    MainWindow window;
    window.composer()->setRequestText(kRequest);
    QStringList written;
    for (int i = 0; i < SessionController::kMaxRecent + 2; ++i) {
        written.prepend(dir.filePath(QStringLiteral("s%1.mbscope.json").arg(i)));
        QVERIFY(window.session()->saveAs(written.constFirst()));
    }
    QCOMPARE(window.session()->recentFiles(), written.mid(0, SessionController::kMaxRecent));
}

// The shipped example has a test plan, a profile and a poll of a named request: the window shows
// the polled request, and saving it back changes none of the rest.
void TestSessionMenu::savingKeepsWhatTheWindowDoesNotShow()
{
    const QString example = QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../docs/examples/rosrao-gamma.mbscope.json");
    const SessionLoadResult original = SessionReader::load(example);
    QVERIFY2(original.ok(), qPrintable(original.errorText()));
    QVERIFY(!original.document->plan.empty());

    MainWindow window;
    QVERIFY(window.session()->open(example));
    QVERIFY(!window.session()->isModified());
    const SessionRequest *polled = original.document->request(original.document->poll->requests.constFirst());
    QCOMPARE(window.composer()->rawEditor()->text().trimmed(), polled->hex.trimmed());
    QCOMPARE(window.composer()->countSpin()->value(), int(original.document->poll->count));

    QTemporaryDir dir;
    const QString copy = dir.filePath(QStringLiteral("copy.mbscope.json"));
    QVERIFY(window.session()->saveAs(copy));
    const SessionLoadResult written = SessionReader::load(copy);
    QVERIFY2(written.ok(), qPrintable(written.errorText()));
    SessionDocument expected = *original.document;
    expected.target = written.document->target; // the connection bar writes the URL in full
    QCOMPARE(written.document->plan, expected.plan);
    QCOMPARE(written.document->profile, expected.profile);
    QCOMPARE(written.document->poll, expected.poll);
    for (const SessionRequest &request : expected.requests) {
        QVERIFY2(written.document->request(request.name), qPrintable(request.name));
        QCOMPARE(*written.document->request(request.name), request);
    }
    QCOMPARE(written.document->name, expected.name);
}

void TestSessionMenu::versionOneSavedSaysUpgraded()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("old.mbscope.json"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"format\": \"mbscope-session\", \"version\": 1, \"name\": \"before watches\"}");
    }
    MainWindow window;
    QVERIFY(window.session()->open(path));
    QSignalSpy notices(window.session(), &SessionController::saveNotice);
    QVERIFY(window.session()->saveAs(path));
    QCOMPARE(notices.size(), 1);
    QVERIFY2(window.statusBar()->currentMessage().contains(QLatin1String("upgraded from session version 1 to 2")),
             qPrintable(window.statusBar()->currentMessage()));
    QCOMPARE(SessionReader::load(path).version, 2);
    QVERIFY(window.session()->saveAs(path)); // version 2 now: nothing to say
    QCOMPARE(notices.size(), 1);
}

void TestSessionMenu::watchesKeptWhenSaved()
{
    const QString example = QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../docs/examples/three-devices.mbscope.json");
    const SessionLoadResult original = SessionReader::load(example);
    QVERIFY2(original.ok(), qPrintable(original.errorText()));
    QCOMPARE(original.document->watches.watches.size(), 3);
    MainWindow window;
    QVERIFY(window.session()->open(example));
    QTemporaryDir dir;
    const QString copy = dir.filePath(QStringLiteral("copy.mbscope.json"));
    QVERIFY(window.session()->saveAs(copy));
    const SessionLoadResult written = SessionReader::load(copy);
    QVERIFY2(written.ok(), qPrintable(written.errorText()));
    QCOMPARE(written.document->watches, original.document->watches);
}

void TestSessionMenu::tapKeptWhenSaved()
{
    // The connection bar's Tap row goes into the session (version 3) and comes back with it; a
    // session without a tap unticks Tap. (Before, the tap's set-up lived only in the settings.)
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("tap.mbscope.json"));
    {
        MainWindow window;
        ConnectionBar *bar = window.connectionBar();
        bar->setUrl(*LinkUrl::parse(QStringLiteral("rtu-tcp://127.0.0.1:4001")).url);
        bar->setTap(true);
        bar->tapFields()->listenEdit()->setText(QStringLiteral("tcp://127.0.0.1:5020 udp://127.0.0.1:5020"));
        bar->tapFields()->routesEdit()->setText(QStringLiteral("20:1=tcp://10.0.0.6:502"));
        bar->tapFields()->readOnlyCheck()->setChecked(true);
        QVERIFY(window.session()->isModified());
        QVERIFY(window.session()->saveAs(path));
    }
    const SessionLoadResult saved = SessionReader::load(path);
    QVERIFY2(saved.ok(), qPrintable(saved.errorText()));
    QCOMPARE(saved.version, 3);
    QVERIFY(saved.document->tap);
    QCOMPARE(saved.document->tap->listen, (QStringList{QStringLiteral("tcp://127.0.0.1:5020"), QStringLiteral("udp://127.0.0.1:5020")}));
    QCOMPARE(saved.document->tap->routes, QStringList{QStringLiteral("20:1=tcp://10.0.0.6:502")});
    QVERIFY(saved.document->tap->readOnly);

    MainWindow window;
    ConnectionBar *bar = window.connectionBar();
    bar->setTap(false);
    bar->tapFields()->listenEdit()->setText(QStringLiteral("tcp://127.0.0.1:9999"));
    QVERIFY(window.session()->open(path));
    QVERIFY(bar->isTap());
    QCOMPARE(bar->tapFields()->listenEdit()->text(), QStringLiteral("tcp://127.0.0.1:5020 udp://127.0.0.1:5020"));
    QCOMPARE(bar->tapFields()->routesEdit()->text(), QStringLiteral("20:1=tcp://10.0.0.6:502"));
    QVERIFY(bar->tapFields()->readOnlyCheck()->isChecked());
    QVERIFY(!window.session()->isModified());
    // The tap the fields make is the one saved: the routes, then the session's target.
    const std::optional<TapSetup> setup = bar->tapSetup();
    QVERIFY2(setup, qPrintable(bar->errorText()));
    QVERIFY2(setup->arguments().join(QLatin1Char(' ')).contains(QLatin1String("--route 20:1=tcp://10.0.0.6:502 --target rtu-tcp://127.0.0.1:4001")),
             qPrintable(setup->arguments().join(QLatin1Char(' '))));
    // Unticking Tap is a change of the document; a session without a tap unticks it.
    bar->setTap(false);
    QVERIFY(window.session()->isModified());
    const QString plain = dir.filePath(QStringLiteral("plain.mbscope.json"));
    QVERIFY(window.session()->saveAs(plain));
    QCOMPARE(SessionReader::load(plain).version, 2);
    QVERIFY(window.session()->open(path));
    QVERIFY(bar->isTap());
    QVERIFY(window.session()->open(plain));
    QVERIFY(!bar->isTap());
}

void TestSessionMenu::layoutIsRememberedPerScreenSize_data()
{
    QTest::addColumn<QSize>("screen");
    QTest::addColumn<QSize>("restored");
    QTest::newRow("the monitor's") << QSize(1920, 1080) << QSize(1600, 1000);
    QTest::newRow("the laptop's") << QSize(1366, 768) << QSize(1200, 700);
    QTest::newRow("a new screen: the last saved") << QSize(2560, 1440) << QSize(1200, 700);
}

// Issue 31: the layout is remembered per screen size; a screen never used gets the last one.
void TestSessionMenu::layoutIsRememberedPerScreenSize()
{
    QFETCH(QSize, screen);
    QFETCH(QSize, restored);
    QSettings().remove(QStringLiteral("window"));
    for (const auto &[on, size] : {std::pair{QSize(1920, 1080), QSize(1600, 1000)}, std::pair{QSize(1366, 768), QSize(1200, 700)}}) {
        MainWindow window;
        window.resize(size);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        WindowLayout::save(window, on);
    }
    MainWindow reopened;
    QVERIFY(WindowLayout::restore(reopened, screen).geometry);
    reopened.show();
    QVERIFY(QTest::qWaitForWindowExposed(&reopened));
    QCOMPARE(reopened.size(), restored);
    QSettings().remove(QStringLiteral("window"));
}

void TestSessionMenu::layoutIsRestored()
{
    {
        MainWindow window;
        window.resize(1111, 777);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QDockWidget *>(QStringLiteral("registersDock"))->hide();
        QVERIFY(window.close());
    }
    MainWindow reopened;
    QVERIFY(reopened.restoreLayout());
    reopened.show();
    QVERIFY(QTest::qWaitForWindowExposed(&reopened));
    QCOMPARE(reopened.size(), QSize(1111, 777));
    QVERIFY(!reopened.findChild<QDockWidget *>(QStringLiteral("registersDock"))->isVisible());
    QVERIFY(reopened.findChild<QDockWidget *>(QStringLiteral("trafficDock"))->isVisible());
}

// The Link column said "link 0": it names the URL the window connected to.
void TestSessionMenu::trafficNamesTheConnectedLink()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(!window.session()->isModified()); // the first run is where an untitled session starts
    QTRY_VERIFY_WITH_TIMEOUT(window.composer()->sendAction()->isEnabled(), 5000);
    window.composer()->send();
    TrafficModel *model = window.trafficMonitor()->model();
    QTRY_VERIFY_WITH_TIMEOUT(model->rowCount() >= 2, 5000);
    const QString link = model->index(0, TrafficModel::LinkColumn).data().toString();
    QVERIFY2(link.contains(QLatin1String("127.0.0.1:")), qPrintable(link));
    QVERIFY2(!link.contains(QLatin1String("link 0")), qPrintable(link));
}

// Try-out 8, item 15: quitting after a plain first run asked "The session (untitled) has changes
// that are not saved" of a user who never made a session. What the next start puts back (the
// target, the composer's request, the poll count) is not asked about; watches made are.
void TestSessionMenu::quitAfterFirstRunAsksNothing()
{
    QSettings().remove(QStringLiteral("composer/request"));
    QSettings().setValue(QStringLiteral("startup/started"), true); // the next start is not a first run
    const QString edited = QStringLiteral("01 03 00 79 00 02 15 DD"); // first-run.md: the quantity 16 made 02
    QString target;
    {
        MainWindow window;
        QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTRY_VERIFY_WITH_TIMEOUT(window.composer()->sendAction()->isEnabled(), 5000);
        window.composer()->send();
        QTRY_VERIFY_WITH_TIMEOUT(window.trafficMonitor()->model()->rowCount() >= 2, 5000);
        window.composer()->setRequestText(edited);
        window.composer()->countSpin()->setValue(5);
        QVERIFY(window.session()->isModified());
        target = window.connectionBar()->url()->toString();
        int asked = 0;
        window.session()->setChangesPrompt([&asked](const QString &) {
            ++asked;
            return SessionController::Choice::Cancel;
        });
        QVERIFY(window.close());
        QCOMPARE(asked, 0);
    }
    {
        // The next start puts back what was not asked about.
        MainWindow window;
        QVERIFY(!window.startAsConfigured());
        QCOMPARE(window.composer()->rawEditor()->text(), edited);
        QCOMPARE(window.connectionBar()->url()->toString(), target);
        QCOMPARE(window.composer()->countSpin()->value(), 5);
        QVERIFY(!window.session()->isModified());

        // A watch is kept by nothing but a session: quitting asks about it.
        WatchDefinition watch;
        watch.name = QStringLiteral("detector");
        watch.target = target;
        watch.function = 3;
        watch.address = 0x79;
        watch.quantity = 2;
        window.watchWorkspace()->addWatch(watch);
        QVERIFY(window.session()->isModified());
        int asked = 0;
        window.session()->setChangesPrompt([&asked](const QString &fileName) {
            ++asked;
            [&] { QCOMPARE(fileName, QStringLiteral("(untitled)")); }();
            return SessionController::Choice::Cancel;
        });
        window.show();
        QVERIFY(!window.close());
        QCOMPARE(asked, 1);
        window.session()->setChangesPrompt([](const QString &) { return SessionController::Choice::Discard; });
    }
}

QTEST_MAIN(TestSessionMenu)
#include "tst_sessionmenu.moc"
