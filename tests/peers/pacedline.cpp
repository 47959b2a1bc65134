#include "pacedline.h"

#include <QtCore/QByteArray>

#include <deque>

#include <cerrno>
#include <cstring>
#include <ctime>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/prctl.h>
#include <termios.h>
#include <unistd.h>

namespace mbscope::testpeers {

namespace {

qint64 nowNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return qint64(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

constexpr qint64 kEarlyWakeNs = 200'000;

// What one end wrote (one read of its pty), passed on when its last character has crossed.
struct Chunk {
    QByteArray bytes;
    qint64 dueNs = 0;
};

} // namespace

PacedLine::~PacedLine()
{
    stop();
}

bool PacedLine::start(qint64 characterNs, QString *error)
{
    m_characterNs = characterNs;
    for (int i = 0; i < 2; ++i) {
        char name[128] = {};
        if (::openpty(&m_master[i], &m_slave[i], name, nullptr, nullptr) != 0) {
            *error = QStringLiteral("openpty: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
            return false;
        }
        // Raw before anyone opens the slave: no echo, no line discipline (the tap and the
        // simulator set their own settings when they open it).
        termios raw{};
        ::tcgetattr(m_slave[i], &raw);
        ::cfmakeraw(&raw);
        ::tcsetattr(m_slave[i], TCSANOW, &raw);
        ::fcntl(m_master[i], F_SETFL, ::fcntl(m_master[i], F_GETFL) | O_NONBLOCK);
        (i == 0 ? m_masterName : m_deviceName) = QString::fromLocal8Bit(name);
    }
    if (::pipe2(m_wake, O_CLOEXEC | O_NONBLOCK) != 0) {
        *error = QStringLiteral("pipe: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    m_stopping = false;
    m_thread = std::thread([this] { run(); });
    return true;
}

void PacedLine::stop()
{
    if (m_thread.joinable()) {
        m_stopping = true;
        const char stopByte = 0;
        (void)!::write(m_wake[1], &stopByte, 1);
        m_thread.join();
    }
    for (int *fd : {&m_master[0], &m_master[1], &m_slave[0], &m_slave[1], &m_wake[0], &m_wake[1]}) {
        if (*fd >= 0)
            ::close(*fd);
        *fd = -1;
    }
}

PacedLine::Timing PacedLine::take()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return std::exchange(m_timing, {});
}

void PacedLine::run()
{
    ::prctl(PR_SET_TIMERSLACK, 1000UL); // wake within a microsecond of the due time, not 50
    std::deque<Chunk> queue[2];         // [0]: to the device, [1]: to the master
    qint64 lineFreeNs = 0;
    qint64 lastInNs[2] = {0, 0};  // the last bytes that came from each end
    qint64 lastOutNs[2] = {0, 0}; // the last bytes handed to each end (just before the write)
    char buffer[4096];
    while (!m_stopping) {
        qint64 nextDue = 0;
        for (const std::deque<Chunk> &q : queue) {
            if (!q.empty() && (nextDue == 0 || q.front().dueNs < nextDue))
                nextDue = q.front().dueNs;
        }
        // Woken 200 us early and spun to the due time, as the product's DueTimer does: the
        // scheduler's wake-up latency would otherwise make every frame late.
        const qint64 waitNs = nextDue == 0 ? 100'000'000 : std::max<qint64>(0, nextDue - kEarlyWakeNs - nowNs());
        const timespec timeout{time_t(waitNs / 1'000'000'000), long(waitNs % 1'000'000'000)};
        pollfd fds[3] = {{m_master[0], POLLIN, 0}, {m_master[1], POLLIN, 0}, {m_wake[0], POLLIN, 0}};
        if (::ppoll(fds, 3, &timeout, nullptr) < 0 && errno != EINTR)
            break;
        for (int end = 0; end < 2; ++end) {
            if ((fds[end].revents & POLLIN) == 0)
                continue;
            const ssize_t n = ::read(m_master[end], buffer, sizeof buffer);
            if (n <= 0)
                continue;
            const qint64 in = nowNs();
            // The first bytes after something was handed to this end: a new frame of this end's,
            // after the other end's.
            if (lastOutNs[end] > lastInNs[end]) {
                std::lock_guard<std::mutex> lock(m_mutex);
                (end == 0 ? m_timing.masterGapsNs : m_timing.turnaroundsNs).push_back(in - lastOutNs[end]);
            }
            lastInNs[end] = in;
            lineFreeNs = std::max(lineFreeNs, in) + qint64(n) * m_characterNs;
            queue[end].push_back(Chunk{QByteArray(buffer, qsizetype(n)), lineFreeNs});
        }
        if (nextDue != 0 && nextDue - nowNs() <= kEarlyWakeNs) {
            while (nowNs() < nextDue) {
            }
        }
        for (int from = 0; from < 2; ++from) {
            std::deque<Chunk> &q = queue[from];
            const int to = 1 - from;
            while (!q.empty() && q.front().dueNs <= nowNs()) {
                const qint64 before = nowNs();
                const ssize_t written = ::write(m_master[to], q.front().bytes.constData(), size_t(q.front().bytes.size()));
                if (written <= 0)
                    break; // the pty is full: again at the next turn
                lastOutNs[to] = before;
                {
                    std::lock_guard<std::mutex> lock(m_mutex);
                    (to == 1 ? m_timing.bytesToDevice : m_timing.bytesToMaster) += written;
                }
                if (written < q.front().bytes.size())
                    q.front().bytes.remove(0, qsizetype(written));
                else
                    q.pop_front();
            }
        }
    }
}

} // namespace mbscope::testpeers
