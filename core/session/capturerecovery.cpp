#include "session/capturerecovery.h"

#include "session/sessiondocument.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>

namespace mbscope {

QString RecoveredCapture::summary() const
{
    const QString name = QFileInfo(journalPath).fileName();
    switch (recovery.ending) {
    case TrafficJournalRecovery::Ending::Clean:
        return QStringLiteral("capture %1: %2").arg(name, recovery.message);
    case TrafficJournalRecovery::Ending::NotClosed:
        return QStringLiteral("capture %1: %2 (the recording was not closed, as after a crash or a kill while capturing; "
                              "every batch written is kept)")
            .arg(name, recovery.message);
    case TrafficJournalRecovery::Ending::CutShort:
        return QStringLiteral("capture %1: %2 (the journal was cut short, as by a crash or a kill while capturing; "
                              "everything up to the last complete batch is kept)")
            .arg(name, recovery.message);
    case TrafficJournalRecovery::Ending::Corrupt:
        return QStringLiteral("capture %1: %2 (the journal is damaged after that point)").arg(name, recovery.message);
    case TrafficJournalRecovery::Ending::NotAJournal:
    case TrafficJournalRecovery::Ending::Unreadable:
        break;
    }
    return QStringLiteral("capture %1: nothing recovered: %2").arg(name, recovery.message);
}

QString CaptureRecovery::journalPath(const SessionDocument &document, const QString &documentPath)
{
    if (!document.capture)
        return {};
    return QDir::cleanPath(QFileInfo(documentPath).absoluteDir().absoluteFilePath(document.capture->journal));
}

RecoveredCapture CaptureRecovery::open(const SessionDocument &document, const QString &documentPath, bool keepFrames)
{
    RecoveredCapture out;
    out.journalPath = journalPath(document, documentPath);
    if (out.journalPath.isEmpty()) {
        out.recovery.message = QStringLiteral("%1: the session has no captured traffic").arg(documentPath);
        return out;
    }
    out.recovery = TrafficJournalReader::readAll(out.journalPath, keepFrames ? &out.frames : nullptr);
    return out;
}

} // namespace mbscope
