#include "mainwindow.h"

#include "decodepanel.h"

#include <QtCore/QCoreApplication>
#include <QtGui/QAction>
#include <QtGui/QKeySequence>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QTabWidget>

namespace mbscope {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_tabs(new QTabWidget(this))
    , m_decodePanel(new DecodePanel(this))
{
    setWindowTitle(QStringLiteral("mbscope"));
    m_tabs->setDocumentMode(true);
    m_tabs->addTab(m_decodePanel, tr("&Decode"));
    setCentralWidget(m_tabs);
    createMenus();
    statusBar()->showMessage(tr("Ready"));
    resize(1000, 620);
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *quit = file->addAction(tr("&Quit"), QCoreApplication::instance(), &QCoreApplication::quit);
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *about = help->addAction(tr("&About mbscope"), this, &MainWindow::showAbout);
    about->setMenuRole(QAction::AboutRole);
}

void MainWindow::showAbout()
{
    // mbscope links QCustomPlot, which is GPL-3.0; the whole program is therefore GPL-3.0-or-later.
    QMessageBox::about(this, tr("About mbscope"),
                       tr("<h3>mbscope %1</h3>"
                          "<p>A bench for testing and analysing Modbus devices: send exactly the bytes "
                          "you mean, see every field of the answer explained, measure how the device "
                          "behaves.</p>"
                          "<p>Licensed under the GNU General Public License, version 3 or (at your "
                          "option) any later version (GPL-3.0-or-later). This program comes with "
                          "ABSOLUTELY NO WARRANTY.</p>"
                          "<p>Built with Qt %2 and QCustomPlot.</p>")
                           .arg(QCoreApplication::applicationVersion().toHtmlEscaped(),
                                QString::fromLatin1(qVersion())));
}

} // namespace mbscope
