#include "toolsmenu.h"

#include "conformance/conformancedialog.h"
#include "discovery/exportmapdialog.h"
#include "discovery/scandialog.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "preferencesdialog.h"
#include "session/recordingcontrol.h"
#include "traffic/trafficmonitor.h"

#include <QtCore/QCoreApplication>
#include <QtGui/QAction>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QStatusBar>

namespace mbscope {

ToolsMenu::ToolsMenu(QMainWindow *window, LinkController *link, ConnectionBar *connectionBar, TrafficMonitor *traffic,
                     RecordingControl *recording)
    : QObject(window)
    , m_window(window)
    , m_link(link)
    , m_connectionBar(connectionBar)
    , m_traffic(traffic)
    , m_recording(recording)
{
}

void ToolsMenu::addMenus(QMenuBar *menuBar)
{
    QMenu *tools = menuBar->addMenu(tr("&Tools"));
    QAction *scan = tools->addAction(tr("&Scan for units\u2026"), this, &ToolsMenu::showScanDialog);
    scan->setObjectName(QStringLiteral("scanAction"));
    scan->setToolTip(tr("Ask every unit id of a link the same read and list what each did"));
    QAction *conform = tools->addAction(tr("&Conformance\u2026"), this, &ToolsMenu::showConformanceDialog);
    conform->setObjectName(QStringLiteral("conformanceAction"));
    conform->setToolTip(tr("Run the conformance battery of mbscope conform against a slave: a verdict per check with its clause"));
    QAction *exportMap = tools->addAction(tr("&Export map\u2026"), this, &ToolsMenu::showExportMapDialog);
    exportMap->setObjectName(QStringLiteral("exportMapAction"));
    exportMap->setToolTip(tr("Write a device profile's register map for Node-RED, Telegraf, Home Assistant, modbus_exporter or CSV, "
                             "verified against the device first if you like (mbscope export-map)"));
    tools->addSeparator();
    QAction *preferences = tools->addAction(tr("&Preferences\u2026"), this, &ToolsMenu::showPreferences);
    preferences->setMenuRole(QAction::PreferencesRole);

    QMenu *help = menuBar->addMenu(tr("&Help"));
    QAction *about = help->addAction(tr("&About mbscope"), this, &ToolsMenu::showAbout);
    about->setMenuRole(QAction::AboutRole);
}

ScanDialog *ToolsMenu::scanDialog()
{
    if (!m_scanDialog) {
        m_scanDialog = new ScanDialog(m_window);
        // The scans' frames, as the watches': the traffic list and the recording.
        connect(m_scanDialog, &ScanDialog::framesLogged, m_traffic, &TrafficMonitor::appendLinkFrames);
        m_scanDialog->setTrafficLog(m_link->trafficLog());
        connect(m_link, &LinkController::trafficLogChanged, m_scanDialog, &ScanDialog::setTrafficLog, Qt::DirectConnection);
        connect(m_scanDialog, &ScanDialog::watchesRequested, this, &ToolsMenu::watchesFound);
    }
    return m_scanDialog;
}

void ToolsMenu::showScanDialog()
{
    ScanDialog *dialog = scanDialog();
    if (!dialog->isRunning()) {
        if (m_link->isConnected())
            dialog->setTarget(m_link->url());
        else if (const ConnectionBar::State state = m_connectionBar->state(); state.target)
            dialog->setTarget(*state.target);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

ConformanceDialog *ToolsMenu::conformanceDialog()
{
    if (!m_conformanceDialog) {
        m_conformanceDialog = new ConformanceDialog(m_window);
        // A run's frames, as a scan's: the traffic list and the recording.
        connect(m_conformanceDialog, &ConformanceDialog::framesLogged, m_traffic, &TrafficMonitor::appendLinkFrames);
        m_conformanceDialog->setTrafficLog(m_link->trafficLog());
        connect(m_link, &LinkController::trafficLogChanged, m_conformanceDialog, &ConformanceDialog::setTrafficLog, Qt::DirectConnection);
    }
    return m_conformanceDialog;
}

void ToolsMenu::showConformanceDialog()
{
    ConformanceDialog *dialog = conformanceDialog();
    if (!dialog->isRunning()) {
        if (m_link->isConnected())
            dialog->setTarget(m_link->url());
        else if (const ConnectionBar::State state = m_connectionBar->state(); state.target)
            dialog->setTarget(*state.target);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

ExportMapDialog *ToolsMenu::exportMapDialog()
{
    if (!m_exportMapDialog)
        m_exportMapDialog = new ExportMapDialog(m_window);
    return m_exportMapDialog;
}

void ToolsMenu::showExportMapDialog()
{
    ExportMapDialog *dialog = exportMapDialog();
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void ToolsMenu::showPreferences()
{
    PreferencesDialog dialog(m_window);
    dialog.setRecordingSettings(m_recording->settings());
    if (dialog.exec() != QDialog::Accepted)
        return;
    const RecordingSettings recording = dialog.recordingSettings();
    if (!(recording == m_recording->settings())) {
        recording.store();
        m_recording->apply(recording);
        status(tr("Recording settings apply from the next connection."));
    }
    if (dialog.apply())
        status(tr("The new language is used when mbscope is started again."));
}

void ToolsMenu::showAbout()
{
    // mbscope links QCustomPlot, which is GPL-3.0; the whole program is therefore GPL-3.0-or-later.
    QMessageBox::about(m_window, tr("About mbscope"),
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

void ToolsMenu::status(const QString &text)
{
    m_window->statusBar()->showMessage(text, 10000);
}

} // namespace mbscope
