#pragma once

#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"

#include <QtCore/QObject>

#include <functional>
#include <memory>

class QAction;
class QWidget;

namespace mbscope {

class WatchCsvLog;

// Logging the watches' values to CSV from the window: the Watches menu's "Log values to CSV"
// (on while the watches run, one file per watch, core/watch's WatchCsvLog) and "CSV log
// settings…" (folder, a row per poll or per change, rolling by size or age). The settings are
// the session's (SessionWatches::log); a folder that is not absolute is the session file's
// folder's, or the capture folder's for an untitled session.
class WatchLogControl : public QObject
{
    Q_OBJECT
public:
    explicit WatchLogControl(QWidget *parent);
    ~WatchLogControl() override;

    [[nodiscard]] QAction *logAction() const { return m_logAction; }
    [[nodiscard]] QAction *settingsAction() const { return m_settingsAction; }

    [[nodiscard]] WatchLogSettings settings() const { return m_settings; }
    // The session's settings (opened, new): not a change of the user's.
    void setSettings(const WatchLogSettings &settings);
    void setSessionPathSource(std::function<QString()> source) { m_sessionPath = std::move(source); }
    // The folder files go to, resolved.
    [[nodiscard]] QString directory() const;

    // The watches start (or changed while running): when logging is on, the files open.
    void start(const SessionWatches &watches);
    // Closes the files (logging stays chosen).
    void stop();
    // The watches stopped: the files close.
    void watchesStopped();
    void append(const QList<WatchSample> &samples);
    [[nodiscard]] bool isLogging() const { return m_log != nullptr; }

    // Replaceable for tests: the settings dialog (true: accepted, settings changed in place).
    using SettingsEditor = std::function<bool(WatchLogSettings &settings)>;
    void setSettingsEditor(SettingsEditor editor) { m_editor = std::move(editor); }

Q_SIGNALS:
    void message(const QString &text);
    // The user changed the settings (the session is modified).
    void settingsChanged();

private:
    void setEnabled(bool enabled);
    bool editSettings();

    QWidget *m_parent;
    QAction *m_logAction;
    QAction *m_settingsAction;
    WatchLogSettings m_settings;
    SessionWatches m_running;
    bool m_watchesRunning = false;
    bool m_failed = false; // a write failed: said once
    std::unique_ptr<WatchCsvLog> m_log;
    std::function<QString()> m_sessionPath;
    SettingsEditor m_editor;
};

} // namespace mbscope
