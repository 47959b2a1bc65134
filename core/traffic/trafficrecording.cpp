#include "trafficrecording.h"

#include <QtCore/QLocale>

namespace mbscope {

namespace {

QString grouped(quint64 n)
{
    return QLocale(QLocale::English, QLocale::UnitedStates).toString(n);
}

} // namespace

TrafficRecording::TrafficRecording() : m_log(TrafficLog::Limits{kMemoryEntries, kMemoryBytes}) {}

TrafficRecording::~TrafficRecording()
{
    close();
}

bool TrafficRecording::open(const QString &path, const TrafficMetadata &metadata, bool overwrite, QString *error,
                            const TrafficJournalWriter::Options &options)
{
    TrafficJournalWriter::Options withMetadata = options;
    withMetadata.metadata = metadata.toUtf8();
    if (!m_log.openJournal(path, withMetadata, overwrite, error))
        return false;
    m_path = path;
    return true;
}

void TrafficRecording::close()
{
    m_log.closeJournal();
}

QString TrafficRecording::summary() const
{
    const quint64 t = transactions();
    QString text = QStringLiteral("recorded %1 frames (%2 %3) to %4")
                       .arg(grouped(frames()), grouped(t), t == 1 ? QStringLiteral("transaction") : QStringLiteral("transactions"), m_path);
    if (!error().isEmpty())
        text += QStringLiteral("; %1, %2 frames lost").arg(error(), grouped(m_log.journal().framesLost()));
    return text;
}

} // namespace mbscope
