#pragma once

#include "session/sessiondocument.h"
#include "watch/watchdefinition.h"
#include "json/profileproblem.h"
#include "compose/savedrequests.h"

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>

class QMainWindow;
class QMenu;

namespace mbscope {

class ConnectionBar;
class RequestComposer;

// The window's session file: New, Open, Save, Save As and Open Recent. A session holds what the
// panels show (the connection bar's target and timeout, the composer's request, its poll
// interval and count, the named requests); the document is made from the panels' states
// (ConnectionBar::State, RequestComposer::State) when saved and put back into them when opened. What the window does not show (the test plan, the profile, a
// form request, the capture) is written back as it was read. Modified means the panels differ from
// what was last saved or opened. Every question to the user (save changes? which file? what was
// wrong in it?) goes through a replaceable function, so tests answer without a modal dialog.
class SessionController : public QObject
{
    Q_OBJECT
public:
    enum class Choice : quint8 { Save, Discard, Cancel };
    // Asked before the session's changes would be lost; fileName is what the title shows.
    using ChangesPrompt = std::function<Choice(const QString &fileName)>;
    // Told why a file was not opened (or not saved): every problem with its JSON path.
    using ProblemReport = std::function<void(const QString &path, const QStringList &problems)>;
    // Asked for a file: forSave true for Save As. Empty: the user cancelled.
    using FileChooser = std::function<QString(bool forSave)>;

    static constexpr int kMaxRecent = 8;
    // The name the composer's current request has in the document (the poll sends it).
    static constexpr const char *kComposerRequest = "composer";

    SessionController(QMainWindow *window, ConnectionBar *bar, RequestComposer *composer);

    // New, Open…, Open Recent, Save, Save As… into menu.
    void addMenuActions(QMenu *menu);

    [[nodiscard]] SessionDocument currentDocument() const;
    [[nodiscard]] bool isModified() const { return m_modified; }
    [[nodiscard]] QString filePath() const { return m_path; }
    [[nodiscard]] QStringList recentFiles() const;
    // The problems of the last open or save that failed ("requests[0].hex: ...").
    [[nodiscard]] QStringList lastProblems() const { return m_lastProblems; }
    // The title the window shows: "bench.mbscope.json* — mbscope", "mbscope" for a fresh window.
    [[nodiscard]] QString windowTitle() const;

    void setChangesPrompt(ChangesPrompt prompt) { m_prompt = std::move(prompt); }
    void setProblemReport(ProblemReport report) { m_report = std::move(report); }
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    // Called by Save and Save As with the document about to be written and its path: the
    // recording puts its journal beside it and names it in the document's capture.
    using BeforeSave = std::function<void(SessionDocument &document, const QString &path)>;
    void setBeforeSave(BeforeSave beforeSave) { m_beforeSave = std::move(beforeSave); }

    // The watches of the window's workspace: read into the document when it is made (saved,
    // compared for the modified flag) and put back when a session is opened or a new one made.
    void setWatchesAccess(std::function<SessionWatches()> get, std::function<void(const SessionWatches &)> set)
    {
        m_getWatches = std::move(get);
        m_setWatches = std::move(set);
    }
    // Something the document holds changed outside the panels the controller watches itself.
    void refreshModified() { updateModified(); }

    // Opens path: false (the problems reported, the panels untouched) when it cannot be read.
    // Does not ask about unsaved changes: openWithPrompt does.
    bool open(const QString &path);
    bool openWithPrompt(const QString &path);
    bool save();
    bool saveAs(const QString &path);
    // A fresh untitled session (target and request as a new window has them), after asking.
    bool newSession();
    // Asks about unsaved changes; true when the caller may go on (saved, discarded, or none).
    bool maybeSave();
    // The same before the window closes. An untitled session (never opened or saved) asks only
    // when it holds something the next start does not put back: the window keeps the target
    // (recent targets), the poll interval and count, the named requests and, when
    // requestComesBack, the composer's request; watches made in the workspace are kept by nothing
    // else. A session with a file asks about any change, as maybeSave().
    bool maybeSaveBeforeQuit(bool requestComesBack);
    // What the panels show now is the session's clean state (after the window set them up).
    void markClean();

Q_SIGNALS:
    void titleChanged(const QString &title);
    // A session was opened (or New put a fresh one in place): its target is in the connection
    // bar now, and the window connects to it, so what the bar shows is what Send uses.
    void targetApplied();
    // Something the user should know about a save that went well: a version 1 document written
    // as version 2 (SessionWriter::save's notice, which older mbscope versions cannot open).
    void saveNotice(const QString &text);

private:
    void updateModified();
    // An untitled session's changes that quitting would lose (see maybeSaveBeforeQuit).
    [[nodiscard]] bool losesWorkOnQuit(bool requestComesBack) const;
    void apply(const SessionDocument &document);
    // The opened document's first polled request, when it is exact bytes the composer can show.
    [[nodiscard]] const SessionRequest *basePolledRequest() const;
    void addRecent(const QString &path);
    void rebuildRecentMenu();
    void setPath(const QString &path);
    void report(const QString &path, const QStringList &problems);

    QMainWindow *m_window;
    ConnectionBar *m_bar;
    RequestComposer *m_composer;
    QMenu *m_recentMenu = nullptr;
    QString m_path;
    SessionDocument m_clean;
    SessionDocument m_base; // the opened document: what the window does not show (plan, profile, ...) is saved back as read
    SessionTarget m_freshTarget; // what New puts back: the connection bar of a new window
    // The composer's named requests when the session was opened (the built-in presets, other
    // windows' requests, the document's own): Save writes only those added or changed since.
    QList<SavedRequest> m_savedAtOpen;
    bool m_modified = false;
    bool m_applying = false;
    QStringList m_lastProblems;
    ChangesPrompt m_prompt;
    ProblemReport m_report;
    FileChooser m_chooser;
    BeforeSave m_beforeSave;
    std::function<SessionWatches()> m_getWatches;
    std::function<void(const SessionWatches &)> m_setWatches;
};

} // namespace mbscope
