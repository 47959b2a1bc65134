#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <atomic>
#include <mutex>
#include <thread>

namespace mbscope::app {

// --json promises one JSON document on standard output, failures included. A subcommand that stops
// before printing its result (a usage error, a file it cannot read, a link that refuses) says why on
// standard error as plain text, as ever; while it runs under this guard both streams pass through
// pipes, unchanged and as they come, and when it ends with a non-zero status having printed nothing
// on standard output, the guard prints there
//   {"error": {"command": "poll", "message": "...", "exit_status": 2}}
// with the message it said on standard error.
class JsonFailureReport
{
public:
    explicit JsonFailureReport(const QString &command);
    ~JsonFailureReport();
    JsonFailureReport(const JsonFailureReport &) = delete;
    JsonFailureReport &operator=(const JsonFailureReport &) = delete;

    // Restores the streams, and prints the error object when status is non-zero and nothing went to
    // standard output. Returns status.
    int finish(int status);

    // Whether standard error was a terminal before the guard put a pipe there (the progress line
    // draws only on a terminal).
    [[nodiscard]] static bool stderrWasTerminal();

private:
    void restore();

    QString m_command;
    int m_savedOut = -1;
    int m_savedErr = -1;
    std::thread m_outPump;
    std::thread m_errPump;
    std::atomic<qint64> m_outBytes{0};
    std::mutex m_errMutex;
    QByteArray m_errText; // the last 64 KiB said on standard error
    bool m_active = false;
};

} // namespace mbscope::app
