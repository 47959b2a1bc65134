#pragma once

#include <QtCore/QDateTime>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// A folder of traffic journals, one (or several parts) per connection, named by start time and
// target: "20261126-001502-rtu-tcp_127.0.0.1_4001.mbscope.journal". A journal being written has
// a marker beside it ("....mbscope.journal.open", holding the writer's process id and host): a
// marker whose process is gone was left by a crash or a kill, and its journal can be recovered.
class CaptureDirectory
{
public:
    static constexpr const char *kSuffix = ".mbscope.journal";
    static constexpr const char *kMarkerSuffix = ".open";

    struct Journal {
        QString path;
        qint64 bytes = 0;
        QDateTime modified;
    };

    explicit CaptureDirectory(QString path = {});
    [[nodiscard]] const QString &path() const { return m_path; }
    // Makes the folder; false with *error saying why.
    bool ensureExists(QString *error) const;

    // A new journal's path for a connection to target starting at start; part > 1 for the parts
    // that follow a rotation. Never the name of a file that exists.
    [[nodiscard]] QString newJournalPath(const QDateTime &start, const QString &target, int part = 1) const;
    // The journals here, oldest first.
    [[nodiscard]] QList<Journal> journals() const;
    // Deletes the oldest journals until those left hold at most maxBytes; never one in keep,
    // nor one still being written (a live marker). The paths deleted.
    QStringList enforceQuota(qint64 maxBytes, const QStringList &keep = {}) const;

    // The marker of a journal this process writes; false with *error when it cannot be made.
    static bool markOpen(const QString &journal, QString *error = nullptr);
    static void markClosed(const QString &journal);
    // Journals whose marker names a process that is gone (this host), newest first.
    [[nodiscard]] QStringList abandoned() const;

private:
    QString m_path;
};

} // namespace mbscope
