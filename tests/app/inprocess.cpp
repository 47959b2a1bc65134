#include "inprocess.h"

#include "commands.h"

#include <QtCore/QFile>
#include <QtCore/QTemporaryFile>

#include <cstdio>
#include <unistd.h>

namespace mbscope::testcli {

namespace {

// One standard stream sent to a temporary file until restore().
class CaughtStream
{
public:
    CaughtStream(std::FILE *stream, int fd)
        : m_stream(stream)
        , m_fd(fd)
    {
        m_file.open();
        std::fflush(m_stream);
        m_saved = ::dup(m_fd);
        ::dup2(m_file.handle(), m_fd);
    }
    QByteArray restore()
    {
        std::fflush(m_stream);
        ::dup2(m_saved, m_fd);
        ::close(m_saved);
        QFile read(m_file.fileName());
        return read.open(QIODevice::ReadOnly) ? read.readAll() : QByteArray();
    }

private:
    std::FILE *m_stream;
    int m_fd;
    int m_saved = -1;
    QTemporaryFile m_file;
};

} // namespace

InProcessRun runInProcess(const QStringList &arguments)
{
    CaughtStream out(stdout, STDOUT_FILENO);
    CaughtStream err(stderr, STDERR_FILENO);
    InProcessRun run;
    run.exitCode = mbscope::app::runHeadless(QStringList{QStringLiteral("mbscope")} + arguments);
    run.out = out.restore();
    run.err = err.restore();
    return run;
}

} // namespace mbscope::testcli
