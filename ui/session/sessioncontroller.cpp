#include "sessioncontroller.h"

#include "common/lastfolder.h"

#include "link/connectionbar.h"
#include "link/tapfields.h"
#include "compose/requestcomposer.h"
#include "compose/savedrequests.h"

#include "protocol/hextext.h"
#include "session/sessionreader.h"
#include "session/sessionwriter.h"
#include "transport/linkurl.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QSettings>
#include <QtGui/QAction>
#include <QtGui/QKeySequence>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMessageBox>

namespace mbscope {

namespace {

const QString kRecentKey = QStringLiteral("session/recent");

} // namespace

SessionController::SessionController(QMainWindow *window, ConnectionBar *bar, RequestComposer *composer)
    : QObject(window)
    , m_window(window)
    , m_bar(bar)
    , m_composer(composer)
{
    m_prompt = [this](const QString &fileName) {
        const QMessageBox::StandardButton answer = QMessageBox::warning(
            m_window, tr("Unsaved changes"),
            tr("The session %1 has changes that are not saved.").arg(fileName),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        if (answer == QMessageBox::Save)
            return Choice::Save;
        return answer == QMessageBox::Discard ? Choice::Discard : Choice::Cancel;
    };
    m_report = [this](const QString &path, const QStringList &problems) {
        // Window-modal but not waited for: the caller goes on (a second start handing its session
        // over is told the problems at once, polls keep running while the box is read).
        auto *box = new QMessageBox(QMessageBox::Warning, tr("Session not opened"),
                                    tr("%1 was not opened; nothing was changed.").arg(QDir::toNativeSeparators(path)),
                                    QMessageBox::Ok, m_window);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setInformativeText(problems.mid(0, 8).join(QLatin1Char('\n')));
        box->setDetailedText(problems.join(QLatin1Char('\n')));
        box->open();
    };
    m_chooser = [this](bool forSave) {
        const QString filter = tr("mbscope sessions (*.mbscope.json *.json);;All files (*)");
        // An untitled session starts where the user last picked a file (LastFolder).
        const QString path = forSave ? QFileDialog::getSaveFileName(m_window, tr("Save session"),
                                                                    m_path.isEmpty() ? LastFolder::start() : m_path, filter)
                                     : QFileDialog::getOpenFileName(m_window, tr("Open session"),
                                                                    m_path.isEmpty() ? LastFolder::start() : QFileInfo(m_path).path(), filter);
        LastFolder::remember(path);
        return path;
    };
    m_savedAtOpen = m_composer->state().savedRequests;
    m_clean = currentDocument();
    m_freshTarget = m_clean.target;
    // Any change of what goes into the document re-checks the modified flag: comparing the
    // document the panels make with the clean one is cheap and cannot miss a field.
    connect(m_bar, &ConnectionBar::stateChanged, this, &SessionController::updateModified);
    connect(m_composer, &RequestComposer::stateChanged, this, &SessionController::updateModified);
}

void SessionController::addMenuActions(QMenu *menu)
{
    QAction *newAction = menu->addAction(tr("&New session"), this, [this] { newSession(); });
    newAction->setShortcut(QKeySequence::New);
    QAction *openAction = menu->addAction(tr("&Open session…"), this, [this] {
        if (!maybeSave())
            return;
        const QString path = m_chooser(false);
        if (!path.isEmpty())
            open(path);
    });
    openAction->setShortcut(QKeySequence::Open);
    m_recentMenu = menu->addMenu(tr("Open &recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &SessionController::rebuildRecentMenu);
    rebuildRecentMenu();
    menu->addSeparator();
    QAction *saveAction = menu->addAction(tr("&Save session"), this, [this] { save(); });
    saveAction->setShortcut(QKeySequence::Save);
    QAction *saveAsAction = menu->addAction(tr("Save session &as…"), this, [this] {
        const QString path = m_chooser(true);
        if (!path.isEmpty())
            saveAs(path);
    });
    saveAsAction->setShortcut(QKeySequence::SaveAs);
}

SessionDocument SessionController::currentDocument() const
{
    SessionDocument d = m_base;
    if (m_getWatches)
        d.watches = m_getWatches();
    const ConnectionBar::State bar = m_bar->state();
    d.target.url = bar.target ? bar.target->toString() : QString();
    d.target.timeoutMs = bar.timeoutMs > 0 ? bar.timeoutMs : -1;
    d.tap.reset();
    if (m_bar->isTap())
        d.tap = m_bar->tapFields()->sessionTap();
    d.requests.clear();
    d.poll.reset();
    const RequestComposer::State composer = m_composer->state();
    const QString current = composer.requestText.trimmed();
    // The composer shows the opened document's polled request: unchanged, it keeps its name and
    // the poll its list.
    const SessionRequest *polled = basePolledRequest();
    const bool samePolled = polled && HexText::parse(polled->hex).bytes == composer.request;
    if (!current.isEmpty() && !composer.request.isEmpty()) {
        SessionRequest request;
        request.name = QString::fromLatin1(kComposerRequest);
        request.hex = current;
        if (samePolled)
            request = *polled;
        d.requests.append(request);
        // A poll "until stopped" has no end a document can hold (a saved poll ends): only the
        // interval and count of a counted poll are kept.
        if (composer.count > 0) {
            SessionPoll poll;
            if (samePolled)
                poll = *m_base.poll;
            else
                poll.requests = {request.name};
            poll.intervalMs = composer.intervalMs;
            poll.count = quint64(composer.count);
            d.poll = poll;
        }
    }
    const QList<SavedRequest> &savedList = composer.savedRequests;
    auto savedNamed = [&savedList](const QString &name) -> const SavedRequest * {
        for (const SavedRequest &saved : savedList) {
            if (saved.name == name)
                return &saved;
        }
        return nullptr;
    };
    // The opened document's requests keep their place (its plan may name them); exact bytes take
    // the composer list's text, forms and completed PDUs stay as read.
    for (SessionRequest request : m_base.requests) {
        if (request.name == QLatin1String(kComposerRequest) || d.request(request.name))
            continue;
        const SavedRequest *saved = savedNamed(request.name);
        if (saved && request.kind == SessionRequest::Kind::Hex && !request.complete)
            request.hex = saved->hex;
        if (request.hexBytes().ok() || request.kind == SessionRequest::Kind::Form)
            d.requests.append(request);
    }
    for (const SavedRequest &saved : savedList) {
        if (saved.name == QLatin1String(kComposerRequest) || d.request(saved.name))
            continue; // the document's names are unique; the composer's request keeps its name
        if (m_savedAtOpen.contains(saved))
            continue; // there before: a built-in preset or another session's, not this one's
        SessionRequest request;
        request.name = saved.name;
        request.hex = saved.hex;
        if (request.hexBytes().ok())
            d.requests.append(request);
    }
    return d;
}

const SessionRequest *SessionController::basePolledRequest() const
{
    if (!m_base.poll || m_base.poll->requests.isEmpty())
        return nullptr;
    const SessionRequest *request = m_base.request(m_base.poll->requests.constFirst());
    return request && request->kind == SessionRequest::Kind::Hex && !request->complete ? request : nullptr;
}

void SessionController::apply(const SessionDocument &document)
{
    m_applying = true;
    if (!document.target.url.isEmpty()) {
        if (const std::optional<LinkUrl> url = LinkUrl::parse(document.target.url).url) {
            m_bar->setState({url, document.target.timeoutMs});
            m_composer->setFraming(url->framing());
        }
    }
    // The Tap row as the document has it; a document without a tap leaves Tap unticked.
    if (document.tap)
        m_bar->tapFields()->setSessionTap(*document.tap);
    m_bar->setTap(document.tap.has_value());
    // The named requests join the composer's list, merged into what QSettings holds now (another
    // window may have added some since this one read it): a name the list has already takes the
    // document's bytes.
    RequestComposer::State composer;
    composer.savedRequests = SavedRequests::load();
    QList<SavedRequest> &saved = composer.savedRequests;
    for (const SessionRequest &request : document.requests) {
        if (request.name == QLatin1String(kComposerRequest) || request.kind != SessionRequest::Kind::Hex
            || request.complete)
            continue;
        const SavedRequest entry{request.name, request.hex};
        const auto it = std::find_if(saved.begin(), saved.end(), [&](const SavedRequest &s) { return s.name == entry.name; });
        if (it == saved.end())
            saved.append(entry);
        else
            *it = entry;
    }
    const SessionRequest *current = document.request(QString::fromLatin1(kComposerRequest));
    if (!current && &document == &m_base)
        current = basePolledRequest();
    composer.requestText = current ? current->hex : QString();
    // A document without a poll gets a new composer's interval and count back.
    if (document.poll) {
        composer.intervalMs = int(document.poll->intervalMs);
        composer.count = int(document.poll->count);
    }
    m_composer->setState(composer);
    if (m_setWatches)
        m_setWatches(document.watches);
    m_savedAtOpen = m_composer->state().savedRequests;
    for (const SessionRequest &request : document.requests) // the document's own stay in it
        m_savedAtOpen.removeIf([&request](const SavedRequest &s) { return s.name == request.name; });
    m_applying = false;
}

bool SessionController::open(const QString &path)
{
    const SessionLoadResult loaded = SessionReader::load(path);
    if (!loaded.ok()) {
        QStringList problems;
        for (const ProfileProblem &problem : loaded.problems) {
            if (!problem.path.isEmpty())
                problems << QStringLiteral("%1: %2").arg(problem.path, problem.message);
            else if (problem.line > 0)
                problems << tr("line %1, column %2: %3").arg(problem.line).arg(problem.column).arg(problem.message);
            else
                problems << problem.message;
        }
        report(path, problems);
        return false;
    }
    m_lastProblems.clear();
    m_base = *loaded.document;
    apply(m_base);
    setPath(QFileInfo(path).absoluteFilePath());
    addRecent(m_path);
    markClean();
    Q_EMIT targetApplied();
    return true;
}

bool SessionController::openWithPrompt(const QString &path)
{
    return maybeSave() && open(path);
}

bool SessionController::save()
{
    if (m_path.isEmpty()) {
        const QString path = m_chooser(true);
        return !path.isEmpty() && saveAs(path);
    }
    return saveAs(m_path);
}

bool SessionController::saveAs(const QString &chosenPath)
{
    // The Open dialog lists *.mbscope.json and *.json: a name without either gets the suffix, so
    // the file saved is a file that can be opened again.
    QString path = chosenPath;
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        path += QLatin1String(".mbscope.json");
    SessionDocument document = currentDocument();
    if (m_beforeSave)
        m_beforeSave(document, QFileInfo(path).absoluteFilePath());
    QString error;
    QString notice;
    if (!SessionWriter::save(document, path, &error, &notice)) {
        report(path, {error});
        return false;
    }
    m_lastProblems.clear();
    m_base.capture = document.capture; // the capture the file now names (the recording's journal)
    setPath(QFileInfo(path).absoluteFilePath());
    addRecent(m_path);
    m_clean = document;
    updateModified();
    if (!notice.isEmpty())
        Q_EMIT saveNotice(notice);
    return true;
}

bool SessionController::newSession()
{
    if (!maybeSave())
        return false;
    SessionDocument fresh;
    fresh.target = m_freshTarget;
    m_base = SessionDocument();
    apply(fresh);
    setPath(QString());
    markClean();
    Q_EMIT targetApplied();
    return true;
}

bool SessionController::maybeSave()
{
    if (!m_modified)
        return true;
    switch (m_prompt(m_path.isEmpty() ? tr("(untitled)") : QFileInfo(m_path).fileName())) {
    case Choice::Save:
        return save();
    case Choice::Discard:
        return true;
    case Choice::Cancel:
        break;
    }
    return false;
}

bool SessionController::maybeSaveBeforeQuit(bool requestComesBack)
{
    // Try-out 8, item 15: a plain first run (the ready request edited, as first-run.md suggests)
    // asked "The session (untitled) has changes that are not saved" of a user who made none.
    if (m_modified && m_path.isEmpty() && !losesWorkOnQuit(requestComesBack))
        return true;
    return maybeSave();
}

bool SessionController::losesWorkOnQuit(bool requestComesBack) const
{
    const QString composerName = QString::fromLatin1(kComposerRequest);
    auto withoutKept = [&](SessionDocument d) {
        d.target = m_clean.target;
        d.poll.reset();
        QList<SessionRequest> lost;
        if (!requestComesBack) {
            if (const SessionRequest *request = d.request(composerName))
                lost.append(*request);
        }
        d.requests = lost;
        return d;
    };
    return withoutKept(currentDocument()) != withoutKept(m_clean);
}

void SessionController::markClean()
{
    m_clean = currentDocument();
    updateModified();
}

void SessionController::updateModified()
{
    if (m_applying)
        return;
    const bool modified = currentDocument() != m_clean;
    const bool changed = modified != m_modified;
    m_modified = modified;
    if (changed)
        Q_EMIT titleChanged(windowTitle());
}

QString SessionController::windowTitle() const
{
    const QString star = m_modified ? QStringLiteral("*") : QString();
    if (m_path.isEmpty())
        return m_modified ? tr("untitled session%1 — mbscope").arg(star) : QStringLiteral("mbscope");
    return tr("%1%2 — mbscope").arg(QFileInfo(m_path).fileName(), star);
}

void SessionController::setPath(const QString &path)
{
    m_path = path;
    Q_EMIT titleChanged(windowTitle());
}

void SessionController::report(const QString &path, const QStringList &problems)
{
    m_lastProblems = problems;
    m_report(path, problems);
}

QStringList SessionController::recentFiles() const
{
    return QSettings().value(kRecentKey).toStringList();
}

void SessionController::addRecent(const QString &path)
{
    QStringList recent = recentFiles();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    QSettings().setValue(kRecentKey, recent);
}

void SessionController::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = recentFiles();
    for (const QString &path : recent) {
        QAction *action = m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] { openWithPrompt(path); });
        action->setToolTip(QDir::toNativeSeparators(path));
    }
    if (recent.isEmpty())
        m_recentMenu->addAction(tr("(none yet)"))->setEnabled(false);
}

} // namespace mbscope
