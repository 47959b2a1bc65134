// The window fits (issue 31, "Fit"): the main screens (first run, decode, traffic, watches,
// analysis, simulator, scan, replay) rendered offscreen at 1024x700, 1400x900 and 1920x1080, light
// and dark, English and Indonesian, and checked mechanically (windowfit.h): the window takes the
// size asked, no widget lies outside its parent, no column title, button or label is cut, no label
// shows a literal '&', every coloured text (verdicts, states, rules) has a contrast of at least
// 4.5:1 against what it is drawn on (WCAG AA), and the analysis plots are at least 300 px high from
// 1400x900 up. Each rendering is kept as windowfit/<lang>-<theme>-<WxH>-<screen>.png in the test's
// output folder (the build tree's tests/ui, a path CI keeps as an artefact), for a person to look at.
#include "guitestsupport.h"
#include "windowfit.h"

#include "common/severitystyle.h"

#include "analysis/analysisdock.h"
#include "common/theme.h"
#include "compose/requestcomposer.h"
#include "decode/transactionview.h"
#include "discovery/scandialog.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "session/replaypanel.h"
#include "shell/mainwindow.h"
#include "shell/preferencesdialog.h"
#include "watch/watchdialog.h"
#include "watch/watchlogdialog.h"
#include "watch/watchprofiledialog.h"
#include "discovery/linescandialog.h"
#include "discovery/mapscandialog.h"
#include "discovery/timingscandialog.h"
#include "shell/sessiontools.h"
#include "shell/translationloader.h"
#include "watch/watchfactory.h"
#include "watch/watchworkspace.h"

#include <QtCore/QDir>
#include <memory>
#include <QtCore/QSettings>
#include <QtGui/QStandardItemModel>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableView>

using namespace mbscope;

namespace {

const QList<QSize> kSizes = {QSize(1024, 700), QSize(1400, 900), QSize(1920, 1080)};
const QStringList kScreens = {QStringLiteral("first-run"), QStringLiteral("decode"), QStringLiteral("traffic"),
                              QStringLiteral("watches"), QStringLiteral("analysis"), QStringLiteral("simulator"),
                              QStringLiteral("scan"), QStringLiteral("replay")};

QDockWidget *dockNamed(MainWindow &window, const QString &name)
{
    return window.findChild<QDockWidget *>(name);
}

void raise(QDockWidget *dock)
{
    dock->show();
    dock->raise();
}

// Puts the window in the state screen names; the dialog rendered instead of the window, if any.
QWidget *showScreen(MainWindow &window, const QString &screen)
{
    window.showTab(QStringLiteral("answer"));
    raise(dockNamed(window, QStringLiteral("trafficDock")));
    if (screen == QLatin1String("decode"))
        window.showTab(QStringLiteral("decode"));
    else if (screen == QLatin1String("watches"))
        window.showTab(QStringLiteral("watches"));
    else if (screen == QLatin1String("analysis"))
        raise(dockNamed(window, QStringLiteral("analysisDock")));
    else if (screen == QLatin1String("simulator"))
        raise(dockNamed(window, QStringLiteral("simulatorDock")));
    else if (screen == QLatin1String("replay"))
        raise(window.sessionTools()->replayDock());
    else if (screen == QLatin1String("scan")) {
        ScanDialog *scan = window.scanDialog();
        scan->show();
        return scan;
    }
    return nullptr;
}

// What mechanically can be seen wrong in root.
QStringList problemsOf(QWidget *root)
{
    QStringList problems;
    problems << windowfit::outsideParent(root) << windowfit::elidedText(root) << windowfit::literalAmpersands(root)
             << windowfit::lowContrast(root) << guitest::mnemonicClashes(root->window());
    return problems;
}

} // namespace

class TestWindowFit : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void checksFindFaults_data();
    void checksFindFaults();
    void contrastOfVerdictColours_data();
    void contrastOfVerdictColours();
    void screens_data();
    void screens();
    void dialogs_data();
    void dialogs();
};

void TestWindowFit::initTestCase()
{
    guitest::isolateSettings();
    QCoreApplication::setApplicationName(QStringLiteral("mbscope-gui-tests-windowfit"));
    QSettings().clear();
    QVERIFY(QDir().mkpath(guitest::outputPath(QStringLiteral("windowfit"))));
}

void TestWindowFit::cleanupTestCase()
{
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
    Theme::apply(Theme::Choice::Light);
}

// Each check finds the fault it is for, on a small window made to have it, and nothing on the
// same window made right.
void TestWindowFit::checksFindFaults_data()
{
    QTest::addColumn<QString>("fault");
    QTest::addColumn<bool>("broken");
    for (const char *fault : {"outside", "header", "button", "label", "ampersand", "contrast"}) {
        QTest::newRow(qPrintable(QStringLiteral("%1 broken").arg(QLatin1String(fault)))) << QString::fromLatin1(fault) << true;
        QTest::newRow(qPrintable(QStringLiteral("%1 right").arg(QLatin1String(fault)))) << QString::fromLatin1(fault) << false;
    }
}

void TestWindowFit::checksFindFaults()
{
    QFETCH(QString, fault);
    QFETCH(bool, broken);
    Theme::apply(Theme::Choice::Light);
    QWidget window;
    window.resize(400, 300);
    QStringList problems;
    // Shown and laid out (a view places its header when it is), then checked.
    auto check = [&window](QStringList (*checker)(QWidget *)) {
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return QStringList{QStringLiteral("the window was not shown")};
        QCoreApplication::processEvents();
        return checker(&window);
    };
    if (fault == QLatin1String("outside")) {
        auto *child = new QWidget(&window);
        child->setGeometry(broken ? QRect(350, 10, 100, 20) : QRect(250, 10, 100, 20));
        problems = check(windowfit::outsideParent);
    } else if (fault == QLatin1String("header")) {
        auto *model = new QStandardItemModel(1, 2, &window);
        model->setHorizontalHeaderLabels({QStringLiteral("Latency (ms)"), QStringLiteral("Verdict")});
        auto *view = new QTableView(&window);
        view->setModel(model);
        view->setGeometry(0, 0, 400, 300);
        view->horizontalHeader()->setStretchLastSection(false);
        view->setColumnWidth(0, broken ? 30 : 150);
        problems = check(windowfit::elidedText);
    } else if (fault == QLatin1String("button")) {
        auto *button = new QPushButton(QStringLiteral("Save traffic as"), &window);
        button->setGeometry(0, 0, broken ? 40 : 200, 30);
        problems = check(windowfit::elidedText);
    } else if (fault == QLatin1String("label")) {
        auto *label = new QLabel(QStringLiteral("<b style=\"color:#1b7f2a\">Connected</b> rtu-tcp://127.0.0.1:4001"), &window);
        label->setGeometry(0, 0, broken ? 60 : 390, 20);
        problems = check(windowfit::elidedText);
    } else if (fault == QLatin1String("ampersand")) {
        auto *label = new QLabel(QStringLiteral("&Profile:"), &window);
        auto *edit = new QLabel(QStringLiteral("x"), &window);
        if (!broken)
            label->setBuddy(edit);
        problems = check(windowfit::literalAmpersands);
    } else if (fault == QLatin1String("contrast")) {
        // The dark "ok" green of the dark theme on the light one's grey, and the light one's.
        auto *label = new QLabel(&window);
        label->setText(QStringLiteral("<b style=\"color:%1\">ok</b>").arg(broken ? QStringLiteral("#81c995") : QStringLiteral("#1b6e2a")));
        label->setGeometry(0, 0, 200, 20);
        problems = check(windowfit::lowContrast);
    }
    QCOMPARE(problems.isEmpty(), !broken);
}

// The verdict colours themselves (traffic, decode, rules) on the backgrounds they are drawn on,
// in both themes: computed from SeverityStyle and the palette, not from a rendering.
void TestWindowFit::contrastOfVerdictColours_data()
{
    QTest::addColumn<bool>("dark");
    QTest::newRow("light") << false;
    QTest::newRow("dark") << true;
}

void TestWindowFit::contrastOfVerdictColours()
{
    QFETCH(bool, dark);
    Theme::apply(dark ? Theme::Choice::Dark : Theme::Choice::Light);
    const QPalette palette = QGuiApplication::palette();
    QStringList problems;
    for (Severity s : {Severity::Ok, Severity::Info, Severity::Warning, Severity::Error}) {
        const QColor text = SeverityStyle::textColor(s);
        for (QPalette::ColorRole role : {QPalette::Base, QPalette::Window, QPalette::AlternateBase}) {
            const double ratio = windowfit::contrast(text, palette.color(role));
            if (ratio < windowfit::kMinimumContrast)
                problems << QStringLiteral("severity %1 text %2 on role %3: %4:1").arg(int(s)).arg(text.name()).arg(int(role)).arg(ratio);
        }
        if (s != Severity::Ok) {
            const double ratio = windowfit::contrast(palette.color(QPalette::Text), SeverityStyle::backgroundColor(s));
            if (ratio < windowfit::kMinimumContrast)
                problems << QStringLiteral("text on severity %1 background: %2:1").arg(int(s)).arg(ratio);
        }
    }
    Theme::apply(Theme::Choice::Light);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestWindowFit::screens_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("theme");
    for (const char *language : {"en", "id"}) {
        for (const char *theme : {"light", "dark"})
            QTest::newRow(qPrintable(QStringLiteral("%1-%2").arg(QLatin1String(language), QLatin1String(theme))))
                << QString::fromLatin1(language) << QString::fromLatin1(theme);
    }
}

// One window per language and theme (the translation is read when widgets are made), taken
// through every size and screen; every problem is listed, with where, before the test fails.
void TestWindowFit::screens()
{
    QFETCH(QString, language);
    QFETCH(QString, theme);
    const bool translated = TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    QCOMPARE(translated, language != QLatin1String("en")); // English is the source: nothing to load
    // Made in the other theme and switched, as Preferences does: what copied a colour of the
    // palette it was made under (the decode view's "ok" in black) shows up on the new one.
    const Theme::Choice chosen = *Theme::parse(theme);
    Theme::apply(chosen == Theme::Choice::Dark ? Theme::Choice::Light : Theme::Choice::Dark);

    MainWindow window;
    window.resize(kSizes.at(1));
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // Something in every view: a short poll fills the traffic list, the registers and the plots;
    // a watch from the composer's read fills the Watches tab.
    QSignalSpy finished(window.controller(), &LinkController::pollFinished);
    window.composer()->intervalSpin()->setValue(10);
    window.composer()->countSpin()->setValue(8);
    window.composer()->togglePoll();
    QVERIFY2(finished.wait(10000), "the first run's poll did not finish");
    const WatchFromRequest watch = WatchFactory::fromRequest(window.composer()->bytes(), window.controller()->url().framing(),
                                                             window.controller()->url().toString(), 1000, {});
    QVERIFY2(watch.error.isEmpty(), qPrintable(watch.error));
    window.watchWorkspace()->addWatch(watch.watch);
    Theme::apply(chosen);

    // Every menu's accelerators, in this language.
    QStringList problems = guitest::repeatedAccelerators(QStringLiteral("menu bar"), window.menuBar()->actions());
    int rendered = 0;
    for (const QSize &size : kSizes) {
        window.resize(size);
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
        if (window.size() != size)
            problems << QStringLiteral("%1x%2: the window cannot be made that size (it is %3x%4, minimum %5x%6)")
                            .arg(size.width()).arg(size.height()).arg(window.width()).arg(window.height())
                            .arg(window.minimumSizeHint().width()).arg(window.minimumSizeHint().height());
        for (const QString &screen : kScreens) {
            QWidget *dialog = showScreen(window, screen);
            QCoreApplication::sendPostedEvents();
            QCoreApplication::processEvents();
            QWidget *root = dialog ? dialog : static_cast<QWidget *>(&window);
            const QString name = QStringLiteral("%1-%2-%3x%4-%5").arg(language, theme).arg(size.width()).arg(size.height()).arg(screen);
            if (!guitest::saveShot(root, QStringLiteral("windowfit/%1.png").arg(name)))
                problems << name + QStringLiteral(": the PNG was not written");
            ++rendered;
            for (const QString &p : problemsOf(root))
                problems << QStringLiteral("%1: %2").arg(name, p);
            // The plots are worth looking at from the default size up.
            if (screen == QLatin1String("analysis") && size.height() >= 900) {
                for (QWidget *plot : window.analysisDock()->findChildren<QWidget *>()) {
                    if (plot->inherits("QCustomPlot") && plot->isVisible())
                        qInfo("%s: plot %dx%d", qPrintable(name), plot->width(), plot->height());
                    if (plot->inherits("QCustomPlot") && plot->isVisible() && plot->height() < 300)
                        problems << QStringLiteral("%1: the plot %2 is %3 px high (300 wanted)")
                                        .arg(name, windowfit::pathOf(plot, &window)).arg(plot->height());
                }
            }
            if (dialog)
                dialog->hide();
        }
    }
    QCOMPARE(rendered, kSizes.size() * kScreens.size());
    problems.removeDuplicates();
    for (const QString &p : std::as_const(problems))
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 problem(s), listed above; the first: %2")
                                                .arg(problems.size()).arg(problems.value(0))));
}

void TestWindowFit::dialogs_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("dialog");
    for (const char *language : {"en", "id"}) {
        for (const char *dialog : {"preferences", "watch", "watch-profile", "watch-log", "map-scan", "line-scan", "timing-scan"})
            QTest::newRow(qPrintable(QStringLiteral("%1-%2").arg(QLatin1String(language), QLatin1String(dialog))))
                << QString::fromLatin1(language) << QString::fromLatin1(dialog);
    }
}

// The dialogs as they open, in both languages: each accelerator once (Alt+P was two things in
// Indonesian), no literal '&' ("&Profile:"), nothing cut or outside.
void TestWindowFit::dialogs()
{
    QFETCH(QString, language);
    QFETCH(QString, dialog);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    Theme::apply(Theme::Choice::Light);
    std::unique_ptr<QDialog> shown;
    if (dialog == QLatin1String("preferences"))
        shown = std::make_unique<PreferencesDialog>();
    else if (dialog == QLatin1String("watch"))
        shown = std::make_unique<WatchDialog>();
    else if (dialog == QLatin1String("watch-profile"))
        shown = std::make_unique<WatchProfileDialog>();
    else if (dialog == QLatin1String("watch-log"))
        shown = std::make_unique<WatchLogDialog>();
    else if (dialog == QLatin1String("map-scan"))
        shown = std::make_unique<MapScanDialog>();
    else if (dialog == QLatin1String("line-scan"))
        shown = std::make_unique<LineScanDialog>();
    else
        shown = std::make_unique<TimingScanDialog>();
    shown->show();
    QVERIFY(QTest::qWaitForWindowExposed(shown.get()));
    QCoreApplication::processEvents();
    QVERIFY(guitest::saveShot(shown.get(), QStringLiteral("windowfit/dialog-%1-%2.png").arg(language, dialog)));
    QStringList problems = problemsOf(shown.get());
    shown.reset();
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
    for (const QString &p : std::as_const(problems))
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.value(0)));
}

QTEST_MAIN(TestWindowFit)
#include "tst_windowfit.moc"
