#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <functional>

class QAction;
class QWidget;

namespace mbscope {

class WatchRunner;

// Logging the watches' values to CSV from the window: the Watches menu's "Log values to CSV"
// (on while the watches run, one file per watch and one of rule events, core/watch's
// WatchCsvLog) and "CSV log settings…" (folder, a row per poll or per change, rolling by size or
// age). The settings are the session's (SessionWatches::log); a folder that is not absolute is
// the session file's folder's, or the working folder's for an untitled session. The rows are
// written by the runner's log thread (WatchRunner::setLog), never the GUI thread; this only says
// what it reports (opened, a write that fails, closed with the rows lost).
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

    // The watches start on runner: when logging is on, its files open (and follow the watches).
    void start(WatchRunner *runner);
    // Closes the files (logging stays chosen).
    void stop();
    // The watches stopped: the runner closes the files.
    void watchesStopped();
    // Files open (said by the runner's log thread).
    [[nodiscard]] bool isLogging() const { return m_open; }

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
    // The runner logs as the settings say (or not, logging off or the watches stopped).
    void apply();
    [[nodiscard]] QString baseDirectory() const;

    QWidget *m_parent;
    QAction *m_logAction;
    QAction *m_settingsAction;
    WatchLogSettings m_settings;
    QPointer<WatchRunner> m_runner;
    bool m_watchesRunning = false;
    bool m_open = false;
    std::function<QString()> m_sessionPath;
    SettingsEditor m_editor;
};

} // namespace mbscope
