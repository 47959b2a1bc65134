#pragma once

#include <QtCore/QFileSystemWatcher>
#include <QtCore/QList>
#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace mbscope {

class ScriptHighlighter;
class SimulatorHost;

// The Script tab's editor: one of the selected simulator's scripts (a unit's, or the delimited
// line's) in a highlighted editor (ScriptHighlighter); Save (Ctrl+S) writes it to its file. The
// file is watched (QFileSystemWatcher): whenever it changes on disk, saved here or by another
// editor, the simulator loads its scripts again (reloadWanted), and the text shown follows the
// file unless it has edits of its own. An error the log reports for the script shown
// ("s.js:2:15: SyntaxError: ...") marks its line in the error colour until a load succeeds.
// Scripts inside the program (":/profiles/...") are shown read-only.
class ScriptEditor : public QWidget
{
    Q_OBJECT
public:
    explicit ScriptEditor(QWidget *parent = nullptr);

    // Shows host's scripts (nullptr: none), the first of them in the editor.
    void setHost(SimulatorHost *host);
    // A line of the scripts' log (SimulatorHost::scriptLogged): an error located in the script
    // shown marks its line; a load of it clears the mark.
    void noteLog(const QString &who, const QString &text, bool error);
    // Writes the editor's text to the script's file; false with the reason in the status line.
    bool save();

    [[nodiscard]] QPlainTextEdit *editor() const { return m_edit; }
    [[nodiscard]] QComboBox *scriptChoice() const { return m_choice; }
    [[nodiscard]] QPushButton *saveButton() const { return m_save; }
    [[nodiscard]] QString path() const;
    // The line marked as the last error's (1-based), 0 when none.
    [[nodiscard]] int errorLine() const { return m_errorLine; }
    [[nodiscard]] QString statusText() const;

Q_SIGNALS:
    // The script's file changed on disk: the simulator should load its scripts again.
    void reloadWanted();

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Script {
        QString who;  // "unit 1: s.js", as the log names it
        QString name; // "s.js", as errors name it
        QString path;
    };
    void show(int index);
    void loadFile();
    void onFileChanged(const QString &path);
    void markError(int line, const QString &message);
    void updateMarks();
    void setStatus(const QString &text, bool problem);

    QPointer<SimulatorHost> m_host;
    QList<Script> m_list;
    int m_current = -1;
    int m_errorLine = 0;
    QComboBox *m_choice = nullptr;
    QPushButton *m_save = nullptr;
    QLabel *m_status = nullptr;
    QPlainTextEdit *m_edit = nullptr;
    ScriptHighlighter *m_highlighter = nullptr;
    QFileSystemWatcher m_watcher;
};

} // namespace mbscope
