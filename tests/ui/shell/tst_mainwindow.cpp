// MainWindow: the title, the menus, and the panels it assembles (connection bar, composer, views).
#include "decode/decodepanel.h"
#include "link/connectionbar.h"
#include "shell/mainwindow.h"
#include "compose/requestcomposer.h"

#include <QtCore/QDir>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtGui/QAction>
#include <QtWidgets/QApplication>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QTabWidget>
#include <QtTest/QtTest>

using namespace mbscope;

class TestMainWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void assemblesThePanels();
    void menus();
    void windowIcon();
    void secondStartHandsOverItsSession_data();
    void secondStartHandsOverItsSession();
};

void TestMainWindow::assemblesThePanels()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(window.windowTitle(), QStringLiteral("mbscope"));
    QVERIFY(window.decodePanel());
    QTabWidget *tabs = window.viewTabs();
    QVERIFY(tabs);
    QVERIFY(tabs->indexOf(window.decodePanel()) >= 0);
    QVERIFY(window.connectionBar()->isVisible());
    QVERIFY(window.composer()->isVisible());
    QVERIFY(window.statusBar()->isVisible());
}

void TestMainWindow::menus()
{
    MainWindow window;
    QStringList titles;
    QStringList actions;
    for (QAction *menuAction : window.menuBar()->actions()) {
        titles << menuAction->text();
        if (QMenu *menu = menuAction->menu()) {
            for (QAction *a : menu->actions())
                actions << a->text();
        }
    }
    QCOMPARE(titles, (QStringList{QStringLiteral("&File"), QStringLiteral("&Request"), QStringLiteral("&Session"), QStringLiteral("Wor&kspace"),
                                  QStringLiteral("&View"), QStringLiteral("&Tools"), QStringLiteral("&Help")}));
    QVERIFY(actions.contains(QStringLiteral("&Find in traffic")));
    QVERIFY(actions.contains(QStringLiteral("&Send")));
    QVERIFY(actions.contains(QStringLiteral("&Quit")));
    QVERIFY(actions.contains(QStringLiteral("&About mbscope")));
    QVERIFY(actions.contains(QStringLiteral("&Replay to the target")));
    QVERIFY(actions.contains(QStringLiteral("Run the test &plan")));
}

// The icon is set at run time (packaging/icons/mbscope.svg compiled in): the window's and the
// application's, for its dialogs, rendered at the desktop's sizes.
void TestMainWindow::windowIcon()
{
    MainWindow window;
    const QIcon icon = window.windowIcon();
    QVERIFY(!icon.isNull());
    QVERIFY(!QApplication::windowIcon().isNull());
    for (const int size : {16, 32, 48, 256}) {
        const QImage image = icon.pixmap(size, size).toImage();
        QCOMPARE(image.size(), QSize(size, size));
        // The rounded corner is transparent; the blue data block sits below the middle.
        QVERIFY(image.pixelColor(0, 0).alpha() < 255);
        const QColor data = image.pixelColor(size / 2, size * 3 / 4);
        QVERIFY2(data.alpha() == 255 && data.blue() > data.red() + 60,
                 qPrintable(QStringLiteral("%1 px: %2 where the data block is").arg(size).arg(data.name(QColor::HexArgb))));
    }
}

void TestMainWindow::secondStartHandsOverItsSession_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("said");
    const QString session = QStringLiteral(MBSCOPE_SOURCE_DIR "/docs/examples/rosrao-gamma.mbscope.json");
    QTest::newRow("session") << QStringList{QStringLiteral("--session"), session} << 0
                             << QStringLiteral("mbscope: ok: the running window (pid %1) opened ") + session;
    QTest::newRow("tab") << QStringList{QStringLiteral("--tab"), QStringLiteral("decode")} << 0
                         << QStringLiteral("mbscope: ok: the running window (pid %1) came forward");
    QTest::newRow("broken session") << QStringList{QStringLiteral("--session"), QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/broken/bad-hex.mbscope.json")}
                                    << 1 << QStringLiteral("mbscope: error: the running window did not open ");
    QTest::newRow("unknown tab") << QStringList{QStringLiteral("--tab"), QStringLiteral("plots")} << 1
                                 << QStringLiteral("mbscope: error: --tab 'plots' names no tab");
    // --new-instance: a window of its own (it quits on its own after MBSCOPE_QUIT_AFTER_MS).
    QTest::newRow("new instance") << QStringList{QStringLiteral("--new-instance"), QStringLiteral("--no-simulator")} << 0 << QString();
}

// Issue 31: a second start of the window hands its arguments to the one running on the same data
// (QLocalServer), which opens the session and comes forward; --new-instance opts out.
void TestMainWindow::secondStartHandsOverItsSession()
{
#ifndef MBSCOPE_BINARY
    QSKIP("built without the mbscope binary");
#else
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, said);
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
    QProcess first;
    first.setProcessEnvironment(env);
    first.start(QStringLiteral(MBSCOPE_BINARY), {});
    QVERIFY2(first.waitForStarted(30000), qPrintable(first.errorString()));
    // The first run's journal is open once the window is up (and listening: it listens before
    // it builds the window).
    const QString captures = home.filePath(QStringLiteral("xdg_data_home/mbscope/mbscope/captures"));
    QTRY_VERIFY_WITH_TIMEOUT(!QDir(captures).entryList({QStringLiteral("*.mbscope.journal.open")}, QDir::Files).isEmpty(), 30000);

    QProcess second;
    env.insert(QStringLiteral("MBSCOPE_QUIT_AFTER_MS"), QStringLiteral("300"));
    second.setProcessEnvironment(env);
    second.start(QStringLiteral(MBSCOPE_BINARY), arguments);
    QVERIFY(second.waitForFinished(30000));
    const QString err = QString::fromLocal8Bit(second.readAllStandardError());
    const qint64 firstPid = first.processId(); // 0 once it ended
    first.terminate();
    QVERIFY(first.waitForFinished(30000));
    QCOMPARE(second.exitCode(), exitCode);
    if (said.isEmpty())
        QVERIFY2(!err.contains(QLatin1String("running window")), qPrintable(err));
    else
        QVERIFY2(err.contains(said.contains(QLatin1String("%1")) ? said.arg(firstPid) : said), qPrintable(err));
#endif
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
