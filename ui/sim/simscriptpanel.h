#pragma once

#include <QtCore/QHash>
#include <QtCore/QPointer>
#include <QtCore/QStringList>
#include <QtWidgets/QWidget>

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSplitter;

namespace mbscope {

class ScriptEditor;
class SimulatorHost;

// The Simulator dock's Script tab: which scripts the selected simulator runs, Reload scripts
// (each loaded again from its file, in the simulator's thread), the script's editor
// (ScriptEditor: highlighted, its error's line marked, loaded again on every save) and beside
// it the scripts' log: their log(...) lines and their errors with file and line, the newest
// kLogLines of each simulator.
class SimScriptPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kLogLines = 2000;

    explicit SimScriptPanel(QWidget *parent = nullptr);

    // Starts keeping host's script log (before it starts: its first lines are the loads).
    void watch(SimulatorHost *host);
    void forget(SimulatorHost *host);
    // The simulator whose scripts and log are shown (nullptr: none).
    void setHost(SimulatorHost *host);
    void reload();

    [[nodiscard]] QString logText() const;
    [[nodiscard]] QPushButton *reloadButton() const { return m_reload; }
    [[nodiscard]] ScriptEditor *editor() const { return m_editor; }

private:
    void append(SimulatorHost *host, const QString &line);

    QPointer<SimulatorHost> m_host;
    QHash<SimulatorHost *, QStringList> m_logs;
    QLabel *m_scripts = nullptr;
    QPushButton *m_reload = nullptr;
    QPushButton *m_clear = nullptr;
    QSplitter *m_split = nullptr;
    ScriptEditor *m_editor = nullptr;
    QPlainTextEdit *m_log = nullptr;
};

} // namespace mbscope
