// The Watches tab end to end: three simulated devices on three links polled at once (the RosRao
// detector over RTU-over-TCP, the M221 PLC over TCP, the Arduino slave on a socat pty), their
// values and counters shown, a value written and a rule firing with its colour, one device
// killed while the others go on, the session saved and reopened with its watches, the main
// tasks by keyboard alone, and screenshots in both themes and both languages.
#include "common/theme.h"
#include "compose/addressfield.h"
#include "compose/requestcomposer.h"
#include "link/linkcontroller.h"
#include "session/sessioncontroller.h"
#include "shell/mainwindow.h"
#include "shell/translationloader.h"
#include "watch/rulepalette.h"
#include "watch/watchdialog.h"
#include "watch/watchlogcontrol.h"
#include "watch/watchtablemodel.h"
#include "watch/watchwindow.h"
#include "watch/watchworkspace.h"

#include "guitestsupport.h"
#include "peerprocess.h"

#include "fleet/watchrunner.h"
#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtGui/QAction>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMdiArea>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QTableView>

#include <memory>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 20000;
const QString kAnyPort = QStringLiteral("rtu-tcp://127.0.0.1:0");

// The three devices of the labs, each behind its own simulator and link.
struct Devices {
    std::unique_ptr<SimulatorHost> rosrao;
    std::unique_ptr<SimulatorHost> m221;
    std::unique_ptr<SimulatorHost> arduino;
    testpeers::PtyPair pty;
    QString rosraoUrl;
    QString m221Url;
    QString arduinoUrl;

    static std::unique_ptr<SimulatorHost> serve(const QString &profile, const QString &url, QString *bound, QString *error)
    {
        const ProfileLoadResult loaded = ProfileLoader::load(profile);
        if (!loaded.ok) {
            *error = loaded.errorText();
            return nullptr;
        }
        auto host = std::make_unique<SimulatorHost>();
        if (!host->load(loaded.profile, error))
            return nullptr;
        const std::optional<LinkUrl> listening = host->listen(url, error);
        if (!listening)
            return nullptr;
        *bound = listening->toString();
        host->start();
        return host;
    }

    bool start(QString *error)
    {
        if (!testpeers::socatAvailable(error) || !pty.start()) {
            if (error->isEmpty())
                *error = pty.error();
            return false;
        }
        QString ignored;
        rosrao = serve(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"), &rosraoUrl, error);
        m221 = serve(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &m221Url, error);
        arduino = serve(QStringLiteral("arduino-rs485"), QStringLiteral("rtu://%1?baud=19200").arg(pty.peerEnd()), &ignored, error);
        arduinoUrl = QStringLiteral("rtu://%1?baud=19200").arg(pty.ourEnd());
        return rosrao && m221 && arduino;
    }
};

WatchDefinition plcWords(const QString &target)
{
    WatchDefinition watch;
    watch.name = QStringLiteral("plc words");
    watch.target = target;
    watch.function = 3;
    watch.address = 0;
    watch.quantity = 10;
    watch.intervalMs = 200;
    WatchPoint setpoint;
    setpoint.address = 0;
    setpoint.name = QStringLiteral("setpoint");
    setpoint.unit = QStringLiteral("rpm");
    setpoint.writable = true;
    watch.points = {setpoint};
    WatchRule rule;
    rule.point = QStringLiteral("setpoint");
    rule.condition = WatchRule::Condition::Above;
    rule.high = 1000;
    rule.severity = WatchSeverity::Alarm;
    rule.message = QStringLiteral("setpoint above 1000 rpm");
    watch.rules = {rule};
    return watch;
}

WatchDefinition plcCoils(const QString &target)
{
    WatchDefinition watch;
    watch.name = QStringLiteral("plc coils");
    watch.target = target;
    watch.function = 1;
    watch.address = 0;
    watch.quantity = 16;
    watch.intervalMs = 200;
    return watch;
}

// The watches of the three devices, made the ways a user makes them: two from device profiles,
// two typed. Returns the index of "plc words".
int addLabWatches(WatchWorkspace *workspace, const Devices &devices)
{
    QString error;
    if (workspace->addFromProfile(QStringLiteral("rosrao-gamma"), 1, devices.rosraoUrl, 200, &error) < 1)
        qWarning("%s", qPrintable(error));
    const int words = workspace->addWatch(plcWords(devices.m221Url));
    workspace->addWatch(plcCoils(devices.m221Url));
    if (workspace->addFromProfile(QStringLiteral("arduino-rs485"), 1, devices.arduinoUrl, 200, &error) < 1)
        qWarning("%s", qPrintable(error));
    return words;
}

bool everyWatchAnswered(WatchWorkspace *workspace, quint64 polls)
{
    for (int i = 0; i < workspace->count(); ++i) {
        if (workspace->window(i)->counters().ok < polls)
            return false;
    }
    return true;
}

} // namespace

class TestWorkspace : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void threeDevicesPolledAtOnce();
    void byKeyboardAlone();
    void csvLogFromTheWindow();
    void csvLogFailureSaid();
    void screenshots_data();
    void screenshots();
};

void TestWorkspace::initTestCase()
{
    guitest::isolateSettings();
}

void TestWorkspace::cleanup()
{
    Theme::apply(Theme::Choice::System);
}

void TestWorkspace::threeDevicesPolledAtOnce()
{
    Devices devices;
    QString error;
    if (!devices.start(&error))
        QSKIP(qPrintable(error));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.mbscope.json"));
    SessionWatches saved;
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.showTab(QStringLiteral("watches")));
        WatchWorkspace *workspace = window.watchWorkspace();
        const int words = addLabWatches(workspace, devices);
        QCOMPARE(workspace->count(), 4); // the detector's registers in one read, the PLC's words and coils, the Arduino's
        QAbstractItemModelTester tester(workspace->window(words)->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
        QVERIFY(window.session()->isModified());

        workspace->startAction()->trigger();
        QVERIFY(workspace->isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(everyWatchAnswered(workspace, 3), kWaitMs);
        // Values in their formats, with names, units and references.
        for (int i = 0; i < workspace->count(); ++i) {
            WatchTableModel *model = workspace->window(i)->model();
            QVERIFY(model->rowCount() > 0);
            QVERIFY2(model->hasValue(0), qPrintable(workspace->watches().watches.at(i).name));
            QVERIFY(workspace->window(i)->countersLabel()->text().contains(QStringLiteral("polls")));
        }
        WatchTableModel *plc = workspace->window(words)->model();
        QCOMPARE(plc->index(0, WatchTableModel::NameColumn).data().toString(), QStringLiteral("setpoint"));
        QCOMPARE(plc->index(0, WatchTableModel::UnitColumn).data().toString(), QStringLiteral("rpm"));
        QCOMPARE(plc->index(0, WatchTableModel::ReferenceColumn).data().toString(), QStringLiteral("40001"));

        // A value written from the table (F2 on its row), read back, and the rule it breaks fires.
        workspace->setCurrentIndex(words);
        QTableView *view = workspace->window(words)->view();
        view->setCurrentIndex(plc->index(0, WatchTableModel::ValueColumn));
        workspace->setTextPrompt([](const QString &, const QString &, const QString &) { return std::optional<QString>(QStringLiteral("1234")); });
        QTest::keyClick(view, Qt::Key_F2);
        QTRY_COMPARE_WITH_TIMEOUT(plc->index(0, WatchTableModel::ValueColumn).data().toString(), QStringLiteral("1234"), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(plc->index(0, WatchTableModel::RuleColumn).data().toString().contains(QStringLiteral("setpoint above 1000 rpm")),
                                 kWaitMs);
        QCOMPARE(plc->index(0, WatchTableModel::ValueColumn).data(Qt::BackgroundRole).value<QColor>(),
                 RulePalette::background(WatchSeverity::Alarm));
        QVERIFY(plc->index(1, WatchTableModel::ValueColumn).data(Qt::BackgroundRole).isNull());
        QTRY_VERIFY_WITH_TIMEOUT(workspace->window(words)->counters().ruleFirings >= 1, kWaitMs);
        // A point not marked writable is not written.
        QString refused;
        QVERIFY(!workspace->writeValue(words, 1, QStringLiteral("5"), &refused));
        QVERIFY2(refused.contains(QStringLiteral("writable")), qPrintable(refused));

        // The PLC dies; the detector and the Arduino go on, the PLC's windows say its link is down.
        QList<quint64> okBefore;
        for (int i = 0; i < workspace->count(); ++i)
            okBefore << workspace->window(i)->counters().ok;
        devices.m221->stop();
        QTRY_VERIFY_WITH_TIMEOUT(workspace->window(words)->linkState() != WatchLinkState::State::Up, kWaitMs);
        QVERIFY2(!workspace->window(words)->countersLabel()->text().contains(QStringLiteral("link: up")),
                 qPrintable(workspace->window(words)->countersLabel()->text()));
        auto othersWentOn = [&] {
            for (int i = 0; i < workspace->count(); ++i) {
                if (workspace->watches().watches.at(i).target == devices.m221Url)
                    continue;
                if (workspace->window(i)->counters().ok < okBefore.at(i) + 5)
                    return false;
            }
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(othersWentOn(), kWaitMs);
        const quint64 plcOk = workspace->window(words)->counters().ok;
        QTest::qWait(600);
        QCOMPARE(workspace->window(words)->counters().ok, plcOk);
        QVERIFY(workspace->window(words)->linkState() != WatchLinkState::State::Up);

        QVERIFY(guitest::saveShot(&window, QStringLiteral("workspace-devices.png")));
        workspace->stopAction()->trigger();
        QVERIFY(!workspace->isRunning());

        // Saved in the session...
        QVERIFY2(window.session()->saveAs(path), qPrintable(window.session()->lastProblems().join(QLatin1Char('\n'))));
        QVERIFY(!window.session()->isModified());
        saved = workspace->watches();
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(json.value(QStringLiteral("version")).toInt(), 2);
    QVERIFY(json.contains(QStringLiteral("watches")));
    // ... and reopened with its watches.
    MainWindow reopened;
    QVERIFY(reopened.session()->open(path));
    QCOMPARE(reopened.watchWorkspace()->count(), int(saved.watches.size()));
    QCOMPARE(reopened.watchWorkspace()->watches().watches, saved.watches);
    reopened.viewTabs()->setCurrentWidget(reopened.watchWorkspace());
    reopened.show();
    QVERIFY(QTest::qWaitForWindowExposed(&reopened));
    QTRY_COMPARE(reopened.watchWorkspace()->currentIndex(), 0); // the first watch in front, not the last
    QVERIFY(!reopened.session()->isModified());
    reopened.watchWorkspace()->moveWatch(0, 1);
    QVERIFY(reopened.session()->isModified());
    QCOMPARE(reopened.watchWorkspace()->watches().watches.at(1).name, saved.watches.at(0).name);
}

// New watch, new watch from the composer's read, start all, next watch, write, stop all: keys only.
void TestWorkspace::byKeyboardAlone()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    WatchWorkspace *workspace = window.watchWorkspace();
    QWidget *focus = window.composer();

    // Ctrl+Shift+R: the composer holds the RosRao read (unit 1, 03, 0x0079, 22 registers).
    QTest::keyClick(focus, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(workspace->count(), 1);
    QCOMPARE(window.viewTabs()->currentWidget(), workspace);
    const WatchDefinition fromRead = workspace->watches().watches.constFirst();
    QCOMPARE(fromRead.address, quint16(0x79));
    QCOMPARE(fromRead.quantity, quint16(22));
    QCOMPARE(fromRead.target, window.controller()->url().toString());

    // Ctrl+Shift+N: the dialog, filled as a user would type.
    workspace->setDialogRunner([](WatchDialog &dialog) {
        dialog.nameEdit()->setText(QStringLiteral("settings"));
        dialog.addressField()->setNotation(AddressField::Notation::Modicon); // as the manual writes it
        dialog.addressField()->setText(QStringLiteral("40122"));
        dialog.quantitySpin()->setValue(1);
        return true; // accepted as typed: the workspace reads the fields
    });
    QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : &window, Qt::Key_N,
                    Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(workspace->count(), 2);
    QCOMPARE(workspace->watches().watches.at(1).name, QStringLiteral("settings"));
    QCOMPARE(workspace->watches().watches.at(1).target, fromRead.target);
    QCOMPARE(workspace->watches().watches.at(1).address, quint16(121));

    QTest::keyClick(QApplication::focusWidget(), Qt::Key_F5);
    QVERIFY(workspace->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(everyWatchAnswered(workspace, 2), kWaitMs);
    const int before = workspace->currentIndex();
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_F6, Qt::ControlModifier);
    QCOMPARE(workspace->currentIndex(), (before + 1) % 2);
    QVERIFY(workspace->window(workspace->currentIndex())->view()->hasFocus());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_F5, Qt::ShiftModifier);
    QVERIFY(!workspace->isRunning());
    // Tabbed or tiled: Ctrl+Shift+T.
    QVERIFY(workspace->isTabbed());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_T, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!workspace->isTabbed());
    // Ctrl+W closes the current watch, with the focus in the workspace only.
    workspace->window(0)->view()->setFocus();
    QTest::keyClick(workspace->window(0)->view(), Qt::Key_W, Qt::ControlModifier);
    QCOMPARE(workspace->count(), 1);
    window.composer()->setFocus();
    QTest::keyClick(window.composer(), Qt::Key_W, Qt::ControlModifier);
    QCOMPARE(workspace->count(), 1);
}

// Logging started from the Workspace menu writes a CSV file per watch while the watches run; the
// log's settings are saved in the session and come back with it.
void TestWorkspace::csvLogFromTheWindow()
{
    QString error;
    QString url;
    std::unique_ptr<SimulatorHost> plc = Devices::serve(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &url, &error);
    QVERIFY2(plc, qPrintable(error));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("logged.mbscope.json"));
    {
        MainWindow window;
        WatchWorkspace *workspace = window.watchWorkspace();
        workspace->addWatch(plcWords(url));
        workspace->addWatch(plcCoils(url));
        workspace->logControl()->setSettingsEditor([](WatchLogSettings &settings) {
            settings.directory = QStringLiteral("logs"); // beside the session file
            settings.mode = WatchLogSettings::Mode::EveryPoll;
            settings.enabled = true;
            return true;
        });
        QVERIFY(window.session()->saveAs(path));
        workspace->logControl()->logAction()->trigger();
        QVERIFY(workspace->logControl()->logAction()->isChecked());
        QVERIFY(window.session()->isModified());
        QCOMPARE(workspace->logControl()->directory(), QDir(dir.path()).filePath(QStringLiteral("logs")));
        workspace->startAll();
        QTRY_VERIFY_WITH_TIMEOUT(workspace->logControl()->isLogging(), kWaitMs); // said by the log thread
        QTRY_VERIFY_WITH_TIMEOUT(everyWatchAnswered(workspace, 4), kWaitMs);
        workspace->stopAll();
        QTRY_VERIFY_WITH_TIMEOUT(!workspace->logControl()->isLogging(), kWaitMs);
        QVERIFY(window.session()->save());
    }
    const QStringList files = QDir(dir.filePath(QStringLiteral("logs"))).entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name);
    QCOMPARE(files.size(), 2);
    for (const QString &name : files) {
        QFile csv(QDir(dir.filePath(QStringLiteral("logs"))).filePath(name));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = csv.readAll().split('\n');
        QVERIFY2(lines.size() >= 5, qPrintable(name)); // the header and a row per poll
    }
    MainWindow reopened;
    QVERIFY(reopened.session()->open(path));
    const std::optional<WatchLogSettings> log = reopened.watchWorkspace()->watches().log;
    QVERIFY(log.has_value());
    QCOMPARE(log->directory, QStringLiteral("logs"));
    QVERIFY(log->enabled);
    QVERIFY(reopened.watchWorkspace()->logControl()->logAction()->isChecked());
    plc->stop();
}

// A log folder that cannot be made (a file stands where it would go) is said in the window's
// messages, once, and the watches poll on.
void TestWorkspace::csvLogFailureSaid()
{
    QString error;
    QString url;
    std::unique_ptr<SimulatorHost> plc = Devices::serve(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &url, &error);
    QVERIFY2(plc, qPrintable(error));
    QTemporaryDir dir;
    QFile blocker(dir.filePath(QStringLiteral("blocker")));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    WatchWorkspace workspace;
    QSignalSpy messages(&workspace, &WatchWorkspace::message);
    SessionWatches watches;
    watches.watches.append(plcWords(url));
    WatchLogSettings log;
    log.enabled = true;
    log.directory = dir.filePath(QStringLiteral("blocker/logs"));
    watches.log = log;
    workspace.setWatches(watches);
    workspace.startAll();
    const auto said = [&messages](const QString &part) {
        int n = 0;
        for (const QList<QVariant> &m : std::as_const(messages))
            n += m.constFirst().toString().contains(part) ? 1 : 0;
        return n;
    };
    QTRY_VERIFY_WITH_TIMEOUT(said(QStringLiteral("The CSV log cannot be written")) == 1, kWaitMs);
    QVERIFY(said(QStringLiteral("blocker/logs: the log directory cannot be made")) == 1);
    QTRY_VERIFY_WITH_TIMEOUT(everyWatchAnswered(&workspace, 3), kWaitMs);
    QVERIFY(!workspace.logControl()->isLogging());
    workspace.stopAll();
    QCOMPARE(said(QStringLiteral("The CSV log cannot be written")), 1);
    plc->stop();
}

void TestWorkspace::screenshots_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("id") << QStringLiteral("id");
}

void TestWorkspace::screenshots()
{
    QFETCH(QString, language);
    Devices devices;
    QString error;
    if (!devices.start(&error))
        QSKIP(qPrintable(error));
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.showTab(QStringLiteral("watches"));
        WatchWorkspace *workspace = window.watchWorkspace();
        const int words = addLabWatches(workspace, devices);
        workspace->startAll();
        QTRY_VERIFY_WITH_TIMEOUT(everyWatchAnswered(workspace, 2), kWaitMs);
        QString ignored;
        workspace->setCurrentIndex(words);
        QVERIFY(workspace->writeValue(words, 0, QStringLiteral("1500"), &ignored));
        QTRY_VERIFY_WITH_TIMEOUT(workspace->window(words)->model()->activeRules() > 0, kWaitMs);
        workspace->setTabbed(false);
        for (Theme::Choice theme : {Theme::Choice::Light, Theme::Choice::Dark}) {
            Theme::apply(theme);
            QTest::qWait(300);
            QVERIFY(guitest::saveShot(&window, QStringLiteral("workspace-%1-%2.png").arg(Theme::key(theme), language)));
        }
        workspace->stopAll();
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

QTEST_MAIN(TestWorkspace)
#include "tst_workspace.moc"
