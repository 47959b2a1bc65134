#pragma once

#include <QtCore/QString>

#include <cstdio>

namespace mbscope::app {

// The watch service's log: one line per event on standard error, with its level. Under systemd
// (JOURNAL_STREAM names standard error) each line starts with the syslog priority ("<4>"), which
// journald takes as the entry's level and strips (sd-daemon(3)); on a terminal it starts with the
// UTC time instead. Lines below the chosen level are not written.
class ServiceLog
{
public:
    enum class Level : quint8 { Error, Warning, Notice, Info, Debug };

    explicit ServiceLog(std::FILE *stream = stderr);

    void setLevel(Level level) { m_level = level; }
    [[nodiscard]] Level level() const { return m_level; }
    [[nodiscard]] bool isJournal() const { return m_journal; }

    void write(Level level, const QString &message);
    void error(const QString &message) { write(Level::Error, message); }
    void warning(const QString &message) { write(Level::Warning, message); }
    void notice(const QString &message) { write(Level::Notice, message); }
    void info(const QString &message) { write(Level::Info, message); }
    void debug(const QString &message) { write(Level::Debug, message); }

    // "error", "warning", "notice", "info", "debug".
    [[nodiscard]] static bool parseLevel(const QString &text, Level *level);
    [[nodiscard]] static const char *levelName(Level level);

private:
    std::FILE *m_stream;
    Level m_level = Level::Info;
    bool m_journal = false;
};

} // namespace mbscope::app
