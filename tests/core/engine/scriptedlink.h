#pragma once

// A test double for unit tests of the engine: a Link whose peer lives in the same thread and
// answers each write with scripted bytes after scripted delays (QTimer), or closes. It knows
// nothing of Modbus; the scripts in the tests build the answers.

#include "transport/link.h"
#include "transport/monotonicclock.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QTimer>

#include <atomic>
#include <functional>
#include <memory>

namespace mbscope::test {

struct Reply {
    int delayMs = 0;
    QByteArray bytes;
    bool close = false; // the peer closes the connection after the bytes (if any)
};

// index counts the requests the peer has seen on all connections (0 for the first request). A
// write that carries several whole MBAP requests (a pipelined engine writes the requests of one
// turn together) is read as a server reads its stream: the script sees one request at a time.
using PeerScript = std::function<QList<Reply>(const QByteArray &request, int index)>;

// What the peer saw, readable from the test's thread.
struct PeerState {
    std::atomic<int> opens{0};
    std::atomic<int> writes{0};
    std::atomic<bool> refuse{false}; // open() fails with "connection refused"
    // > 0: bytesWritten() comes this long after the write, carrying the time of the write (as a
    // serial link's computed drain time may come after a fast answer).
    std::atomic<int> writtenDelayMs{0};
    // > 0: open() succeeds this long after it is called (a connection that takes time to open).
    std::atomic<int> openDelayMs{0};
};

class ScriptedLink : public Link
{
public:
    ScriptedLink(const LinkUrl &url, PeerScript script, std::shared_ptr<PeerState> state, QObject *parent)
        : Link(url, parent)
        , m_script(std::move(script))
        , m_state(std::move(state))
    {
    }

    [[nodiscard]] bool isDatagram() const override { return url().isDatagram(); }
    [[nodiscard]] qint64 turnaroundNs() const override { return qint64(url().serial.turnaroundUs) * 1000; }

    void open() override
    {
        if (state() != State::Closed)
            return;
        setState(State::Opening);
        const int generation = ++m_generation;
        QTimer::singleShot(m_state->openDelayMs.load(), Qt::PreciseTimer, this, [this, generation] {
            if (generation != m_generation || state() != State::Opening)
                return;
            ++m_state->opens;
            if (m_state->refuse) {
                setState(State::Closed);
                reportError(LinkError::Kind::Refused, QStringLiteral("connection refused by the scripted peer"));
                return;
            }
            setState(State::Open);
            emit opened();
        });
    }

    void close() override
    {
        ++m_generation;
        setClosed(QStringLiteral("closed on request"));
    }

    bool write(const QByteArray &bytes) override
    {
        if (state() != State::Open) {
            reportError(LinkError::Kind::Closed, QStringLiteral("cannot write: the link is not open"));
            return false;
        }
        const int generation = m_generation;
        if (const int delay = m_state->writtenDelayMs; delay > 0) {
            const qint64 writtenNs = monotonicNowNs();
            QTimer::singleShot(delay, Qt::PreciseTimer, this, [this, generation, writtenNs] {
                if (generation == m_generation)
                    emit bytesWritten(writtenNs);
            });
        } else {
            emit bytesWritten(monotonicNowNs());
        }
        QList<Reply> replies;
        for (const QByteArray &request : requestsIn(bytes))
            replies += m_script(request, m_state->writes++);
        for (const Reply &reply : replies) {
            QTimer::singleShot(reply.delayMs, Qt::PreciseTimer, this, [this, generation, reply] {
                if (generation != m_generation || state() != State::Open)
                    return;
                if (!reply.bytes.isEmpty()) {
                    const qint64 now = monotonicNowNs();
                    emit bytesReceived(reply.bytes, now, now);
                }
                if (reply.close) {
                    ++m_generation;
                    reportLoss(LinkError::Kind::Closed, QStringLiteral("the scripted peer closed the connection"));
                }
            });
        }
        return true;
    }

private:
    // The MBAP requests of a write on a tcp:// stream when it is made of whole ones (Messaging on
    // TCP/IP V1.0b, 3.1.3: the length field counts the bytes after it); the write as it is else.
    [[nodiscard]] QList<QByteArray> requestsIn(const QByteArray &bytes) const
    {
        if (url().framing() != Framing::Tcp || url().isDatagram() || url().delimited.enabled)
            return {bytes};
        QList<QByteArray> requests;
        qsizetype at = 0;
        while (bytes.size() - at >= 7) {
            const qsizetype length = 6 + (quint8(bytes.at(at + 4)) << 8 | quint8(bytes.at(at + 5)));
            if (length > bytes.size() - at)
                break;
            requests.append(bytes.mid(at, length));
            at += length;
        }
        if (at != bytes.size() || requests.size() < 2)
            return {bytes};
        return requests;
    }

    PeerScript m_script;
    std::shared_ptr<PeerState> m_state;
    int m_generation = 0;
};

} // namespace mbscope::test
