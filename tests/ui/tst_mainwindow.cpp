// MainWindow: the title, the menus the issue asks for, and the decode panel in the central area.
#include "decodepanel.h"
#include "mainwindow.h"

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
    auto *tabs = qobject_cast<QTabWidget *>(window.centralWidget());
    QVERIFY(tabs);
    QCOMPARE(tabs->currentWidget(), window.decodePanel());
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
    QCOMPARE(titles, (QStringList{QStringLiteral("&File"), QStringLiteral("&Help")}));
    QVERIFY(actions.contains(QStringLiteral("&Quit")));
    QVERIFY(actions.contains(QStringLiteral("&About mbscope")));
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
