#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtCore/QObject>

class QMainWindow;
class QMenuBar;

namespace mbscope {

class ConformanceDialog;
class ConnectionBar;
class ExportMapDialog;
class LinkController;
class RecordingControl;
class ScanDialog;
class TrafficMonitor;

// The Tools menu (Scan for units, Conformance, Export map, Preferences) and the Help menu (About). The scan dialog is made
// when first asked for; its frames reach the traffic list and the connection's recording as the
// composer's do, and the units it finds are offered to the window as watches (watchesFound).
// MainWindow makes one and adds its menus.
class ToolsMenu : public QObject
{
    Q_OBJECT
public:
    ToolsMenu(QMainWindow *window, LinkController *link, ConnectionBar *connectionBar, TrafficMonitor *traffic,
              RecordingControl *recording);

    // "Tools" and "Help", in that order, at the end of the menu bar.
    void addMenus(QMenuBar *menuBar);
    // Tools > Scan's dialog (made on first use).
    [[nodiscard]] ScanDialog *scanDialog();
    // Opens the scan dialog on the window's target: the connected link, else what the
    // connection bar makes.
    void showScanDialog();
    // Tools > Conformance's dialog (made on first use), opened on the window's target as the scan's is.
    [[nodiscard]] ConformanceDialog *conformanceDialog();
    void showConformanceDialog();
    // Tools > Export map's dialog (made on first use): mbscope export-map from the window.
    [[nodiscard]] ExportMapDialog *exportMapDialog();
    void showExportMapDialog();

Q_SIGNALS:
    // "Add as watches" in the scan dialog.
    void watchesFound(const QList<mbscope::WatchDefinition> &found);

private:
    void showPreferences();
    void showAbout();
    void status(const QString &text);

    QMainWindow *m_window;
    LinkController *m_link;
    ConnectionBar *m_connectionBar;
    TrafficMonitor *m_traffic;
    RecordingControl *m_recording;
    ScanDialog *m_scanDialog = nullptr;
    ConformanceDialog *m_conformanceDialog = nullptr;
    ExportMapDialog *m_exportMapDialog = nullptr;
};

} // namespace mbscope
