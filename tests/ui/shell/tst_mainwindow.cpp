// MainWindow: the title, the menus, and the panels it assembles (connection bar, composer, views).
#include "decode/decodepanel.h"
#include "link/connectionbar.h"
#include "shell/mainwindow.h"
#include "compose/requestcomposer.h"

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

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
