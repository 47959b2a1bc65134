// MainWindow: the title, the menus, and the panels it assembles (connection bar, composer, views).
#include "decodepanel.h"
#include "connectionbar.h"
#include "mainwindow.h"
#include "requestcomposer.h"

#include <QtGui/QAction>
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
    QCOMPARE(titles, (QStringList{QStringLiteral("&File"), QStringLiteral("&Request"), QStringLiteral("&View"),
                                  QStringLiteral("&Tools"), QStringLiteral("&Help")}));
    QVERIFY(actions.contains(QStringLiteral("&Find in traffic")));
    QVERIFY(actions.contains(QStringLiteral("&Send")));
    QVERIFY(actions.contains(QStringLiteral("&Quit")));
    QVERIFY(actions.contains(QStringLiteral("&About mbscope")));
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
