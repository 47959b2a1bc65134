#pragma once

#include "recordingsettings.h"

#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

class LinkController;
class NoticeBanner;
class ReplayController;
class SessionController;
struct SessionDocument;

// The window's recording: every connection journaled into the capture folder (LinkController,
// RollingCapture) as the Preferences say, a saved session's journal beside it and named in its
// capture, and after a crash or kill the offer to open the journal it left, with what came back.
class RecordingControl : public QObject
{
    Q_OBJECT
public:
    RecordingControl(LinkController *link, SessionController *session, ReplayController *replay, QObject *parent);

    // The banner that offers a recovery (the window places it).
    [[nodiscard]] NoticeBanner *recoveryBanner() const { return m_banner; }
    [[nodiscard]] const RecordingSettings &settings() const { return m_settings; }
    // New settings apply from the next connection.
    void apply(const RecordingSettings &settings);

    // Looks for a journal a crash left in the capture folder; shows the offer when there is one.
    // The journal offered, or empty.
    QString offerRecovery();
    // The offer's "Open": the journal goes to the traffic list and analysis (as File > Open
    // capture would) and is no longer offered.
    bool recover();
    void dismissRecovery();

    // Save and Save As: the journal being written goes beside the session file and the
    // document's capture names it.
    void beforeSave(SessionDocument &document, const QString &sessionPath);

Q_SIGNALS:
    void message(const QString &text);

private:
    void onRecordingChanged(const QString &path, const QString &problem);

    LinkController *m_link;
    ReplayController *m_replay;
    NoticeBanner *m_banner;
    RecordingSettings m_settings;
    QString m_offered; // the journal the banner offers
};

} // namespace mbscope
