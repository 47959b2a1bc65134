#include "common/jsonfailure.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

#include <cerrno>
#include <cstdio>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace mbscope::app {

namespace {

constexpr qsizetype kKeptErrorBytes = 64 * 1024;

std::atomic<int> g_stderrTerminal{-1}; // -1: no guard ran, ask isatty

#ifdef Q_OS_UNIX
void writeAll(int fd, const char *data, ssize_t size)
{
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size_t(size));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return;
        data += n;
        size -= n;
    }
}
#endif

} // namespace

JsonFailureReport::JsonFailureReport(const QString &command)
    : m_command(command)
{
#ifdef Q_OS_UNIX
    int outPipe[2];
    int errPipe[2];
    if (::pipe(outPipe) != 0)
        return;
    if (::pipe(errPipe) != 0) {
        ::close(outPipe[0]);
        ::close(outPipe[1]);
        return;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    g_stderrTerminal = ::isatty(STDERR_FILENO) == 1 ? 1 : 0;
    m_savedOut = ::dup(STDOUT_FILENO);
    m_savedErr = ::dup(STDERR_FILENO);
    ::dup2(outPipe[1], STDOUT_FILENO);
    ::dup2(errPipe[1], STDERR_FILENO);
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    const int outRead = outPipe[0];
    const int errRead = errPipe[0];
    m_outPump = std::thread([this, outRead] {
        char buffer[16384];
        for (;;) {
            const ssize_t n = ::read(outRead, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            m_outBytes += n;
            writeAll(m_savedOut, buffer, n);
        }
        ::close(outRead);
    });
    m_errPump = std::thread([this, errRead] {
        char buffer[16384];
        for (;;) {
            const ssize_t n = ::read(errRead, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            writeAll(m_savedErr, buffer, n);
            const std::lock_guard<std::mutex> lock(m_errMutex);
            m_errText.append(buffer, n);
            if (m_errText.size() > kKeptErrorBytes)
                m_errText.remove(0, m_errText.size() - kKeptErrorBytes);
        }
        ::close(errRead);
    });
    m_active = true;
#endif
}

JsonFailureReport::~JsonFailureReport()
{
    restore();
}

void JsonFailureReport::restore()
{
#ifdef Q_OS_UNIX
    if (!m_active)
        return;
    m_active = false;
    std::fflush(stdout);
    std::fflush(stderr);
    // Putting the saved descriptors back closes the pipes' last write ends: the pumps read to the end.
    ::dup2(m_savedOut, STDOUT_FILENO);
    ::dup2(m_savedErr, STDERR_FILENO);
    m_outPump.join();
    m_errPump.join();
    ::close(m_savedOut);
    ::close(m_savedErr);
#endif
}

int JsonFailureReport::finish(int status)
{
    restore();
    if (status == 0 || m_outBytes > 0)
        return status;
    QString message = QString::fromLocal8Bit(m_errText).trimmed();
    if (message.isEmpty())
        message = QStringLiteral("mbscope %1 failed without a message (exit status %2)").arg(m_command).arg(status);
    const QJsonObject error{{QStringLiteral("command"), m_command},
                            {QStringLiteral("message"), message},
                            {QStringLiteral("exit_status"), status}};
    const QByteArray json = QJsonDocument(QJsonObject{{QStringLiteral("error"), error}}).toJson(QJsonDocument::Indented);
    std::fwrite(json.constData(), 1, size_t(json.size()), stdout);
    std::fflush(stdout);
    return status;
}

bool JsonFailureReport::stderrWasTerminal()
{
    const int known = g_stderrTerminal;
    if (known >= 0)
        return known == 1;
#ifdef Q_OS_UNIX
    return ::isatty(STDERR_FILENO) == 1;
#else
    return false;
#endif
}

} // namespace mbscope::app
