#include "recordingcontrol.h"

#include "common/noticebanner.h"
#include "link/linkcontroller.h"
#include "session/replaycontroller.h"
#include "session/sessioncontroller.h"

#include "session/sessiondocument.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QLocale>

namespace mbscope {

namespace {

// How the recovered journal ends, in the window's language (the core's message is English).
QString recoveryEnding(const TrafficJournalRecovery &r)
{
    const QLocale locale;
    switch (r.ending) {
    case TrafficJournalRecovery::Ending::Clean:
        return RecordingControl::tr("it ends cleanly, at byte %1").arg(locale.toString(r.fileBytes));
    case TrafficJournalRecovery::Ending::NotClosed:
        return RecordingControl::tr("it stops after the last complete batch, at byte %1; what was not written yet is not in it")
            .arg(locale.toString(r.fileBytes));
    case TrafficJournalRecovery::Ending::CutShort:
        return RecordingControl::tr("the last batch was cut short at byte %1 and is left out").arg(locale.toString(r.fileBytes));
    case TrafficJournalRecovery::Ending::Corrupt:
        return RecordingControl::tr("the batch at byte %1 is damaged: it and all after it are left out")
            .arg(locale.toString(r.goodBytes));
    case TrafficJournalRecovery::Ending::NotAJournal:
    case TrafficJournalRecovery::Ending::Unreadable:
        break;
    }
    return r.message;
}

} // namespace

RecordingControl::RecordingControl(LinkController *link, SessionController *session, ReplayController *replay,
                                   QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_replay(replay)
    , m_banner(new NoticeBanner)
    , m_settings(RecordingSettings::load())
{
    m_banner->setObjectName(QStringLiteral("recoveryBanner"));
    connect(m_banner, &NoticeBanner::linkActivated, this, [this](const QString &href) {
        if (href == u"open")
            recover();
        else
            dismissRecovery();
    });
    connect(m_banner, &NoticeBanner::dismissed, this, &RecordingControl::dismissRecovery);
    connect(m_link, &LinkController::recordingChanged, this, &RecordingControl::onRecordingChanged);
    session->setBeforeSave([this](SessionDocument &document, const QString &path) { beforeSave(document, path); });
    apply(m_settings);
}

void RecordingControl::apply(const RecordingSettings &settings)
{
    m_settings = settings;
    m_link->setRecording(settings.enabled, settings.directory(), settings.policy());
}

void RecordingControl::onRecordingChanged(const QString &path, const QString &problem)
{
    if (!problem.isEmpty() && !path.isEmpty()) {
        // It stopped on its own: said where it stays in sight until dismissed, as a recovery is.
        m_offered.clear();
        m_banner->showNotice(tr("<b>Not recording any more</b>: %1.").arg(problem.toHtmlEscaped()));
        Q_EMIT message(tr("Not recording: %1").arg(problem));
    } else if (!problem.isEmpty())
        Q_EMIT message(tr("Not recording: %1").arg(problem));
    else if (!path.isEmpty())
        Q_EMIT message(tr("Recording to %1").arg(QDir::toNativeSeparators(path)));
}

QString RecordingControl::offerRecovery()
{
    const QStringList left = m_settings.directory().abandoned();
    if (left.isEmpty())
        return {};
    m_offered = left.constFirst();
    quint64 requests = 0;
    const TrafficJournalRecovery r = TrafficJournalReader::read(m_offered, [&requests](const TrafficEntry &e) {
        requests += e.direction == TrafficDirection::Out ? 1 : 0;
    });
    const QLocale locale;
    QString text = tr("<b>mbscope stopped without closing its last recording</b> (%1, %2). %3 requests came back, "
                      "%4 frames in all: %5.")
                       .arg(QFileInfo(m_offered).fileName().toHtmlEscaped(),
                            locale.toString(QFileInfo(m_offered).lastModified(), QLocale::ShortFormat),
                            locale.toString(requests), locale.toString(r.frames), recoveryEnding(r).toHtmlEscaped());
    if (left.size() > 1)
        text += tr(" %n older recording(s) were also left open.", nullptr, int(left.size() - 1));
    text += QStringLiteral(" <a href=\"open\">%1</a> &nbsp; <a href=\"keep\">%2</a>")
                .arg(tr("Open it in the traffic list"), tr("Keep it in the capture folder"));
    m_banner->showNotice(text);
    return m_offered;
}

bool RecordingControl::recover()
{
    if (m_offered.isEmpty())
        return false;
    const QString path = std::exchange(m_offered, {});
    CaptureDirectory::markClosed(path);
    m_banner->hide();
    return m_replay->openSource(path);
}

void RecordingControl::dismissRecovery()
{
    if (m_offered.isEmpty()) {
        m_banner->hide(); // a notice that the recording stopped
        return;
    }
    // Kept as it is, under the folder's quota like every other journal; no longer offered.
    CaptureDirectory::markClosed(std::exchange(m_offered, {}));
    m_banner->hide();
}

namespace {

// The capture's notes stay; only the journal it names changes.
void nameJournal(SessionDocument &document, const QString &journal)
{
    SessionCapture capture = document.capture.value_or(SessionCapture{});
    capture.journal = journal;
    document.capture = capture;
}

} // namespace

void RecordingControl::beforeSave(SessionDocument &document, const QString &sessionPath)
{
    const QString recording = m_link->recordingPath();
    if (recording.isEmpty())
        return;
    const QFileInfo session(sessionPath);
    if (QFileInfo(recording).absolutePath() == session.absolutePath()) {
        // Already beside this session (an earlier Save): it goes on growing there.
        nameJournal(document, QFileInfo(recording).fileName());
        return;
    }
    // "bench.mbscope.json" -> "bench-20261126-001502.mbscope.journal": a new file per Save of a
    // new recording, so that an earlier capture of the session is never overwritten.
    QString base = session.fileName();
    for (const QLatin1String suffix : {QLatin1String(".mbscope.json"), QLatin1String(".json")}) {
        if (base.endsWith(suffix)) {
            base.chop(suffix.size());
            break;
        }
    }
    const QString name = base + QDateTime::currentDateTime().toString(QStringLiteral("-yyyyMMdd-HHmmss"))
        + QLatin1String(CaptureDirectory::kSuffix);
    const QString target = session.dir().filePath(name);
    bool copied = false;
    QString error;
    if (!m_link->keepRecordingAt(target, &copied, &error)) {
        Q_EMIT message(tr("The session was saved without its traffic: %1").arg(error));
        return;
    }
    nameJournal(document, name);
    Q_EMIT message(copied ? tr("Traffic so far copied to %1; what comes next is recorded in %2")
                                .arg(QDir::toNativeSeparators(target), QDir::toNativeSeparators(m_link->recordingPath()))
                          : tr("Traffic recorded beside the session: %1").arg(QDir::toNativeSeparators(target)));
}

} // namespace mbscope
