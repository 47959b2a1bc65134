#pragma once

#include <QtCore/QObject>
#include <QtCore/QString>

class QAction;
class QCustomPlot;

namespace mbscope {

// The export every plot in the window offers: "Save plot as…" (PNG, SVG or PDF by the chosen
// name, at the plot's on-screen size) and "Copy plot" (a PNG image on the clipboard), in the
// plot's context menu and as actions a panel can put in its tool bar.
class PlotExportMenu : public QObject
{
    Q_OBJECT

public:
    // baseName: the file name the save dialog suggests, without extension ("latency-histogram").
    PlotExportMenu(QCustomPlot *plot, const QString &baseName);

    [[nodiscard]] QAction *saveAction() const { return m_save; }
    [[nodiscard]] QAction *copyAction() const { return m_copy; }

    // What the actions do, without a dialog (tests, scripts): false with the reason in error.
    bool saveTo(const QString &path, QString *error) const;
    void copyToClipboard() const;

Q_SIGNALS:
    // After a save from the dialog: what was written, or why not (for the status bar).
    void saved(const QString &message);

private:
    void askAndSave();

    QCustomPlot *m_plot;
    QString m_baseName;
    QAction *m_save;
    QAction *m_copy;
};

} // namespace mbscope
