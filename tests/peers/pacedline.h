#pragma once

#include <QtCore/QString>

#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

namespace mbscope::testpeers {

// A serial line between two pseudo-terminals that takes the time a UART takes: what one end
// writes comes out of the other end once its characters have crossed the line, each one
// character time long (start, data, parity and stop bits at the baud rate), the line carrying
// one direction at a time as an RS-485 pair does. A pty alone (socat) passes bytes at once
// whatever the baud rate; behind this relay an RTU slave's answers take their line time, so a
// master (the tap) is held to the line's limit. Each write is passed on whole when its last
// character is due (as a USB adapter hands over what its FIFO gathered): a relay thread that the
// scheduler holds up a few milliseconds would otherwise cut a frame in two with a silence longer
// than t3.5.
//
// The relay also times the line as the master's end sees it: the silence between an answer's
// last byte and the next request's first byte (what the master left between frames; Serial Line
// V1.02, 2.5.1.1 asks for at least t3.5), and the device's turnaround (its request's last byte out
// to its answer's first byte in). Each silence is measured from just before the relay wrote the
// bytes to just after it read the next ones, so it is never shorter than the silence the reading
// end kept (a late relay only lengthens it).
class PacedLine
{
public:
    PacedLine() = default;
    ~PacedLine();
    PacedLine(const PacedLine &) = delete;
    PacedLine &operator=(const PacedLine &) = delete;

    // characterNs 0: bytes pass at once (a pty pair as socat makes it).
    bool start(qint64 characterNs, QString *error);
    void stop();
    // The device paths: the master's end (the tap's target) and the device's end (the slave's).
    [[nodiscard]] const QString &masterEnd() const { return m_masterName; }
    [[nodiscard]] const QString &deviceEnd() const { return m_deviceName; }

    struct Timing {
        std::vector<qint64> masterGapsNs; // answer's last byte delivered to the master .. its next request's first byte
        std::vector<qint64> turnaroundsNs; // request's last byte delivered to the device .. its answer's first byte
        long long bytesToDevice = 0;
        long long bytesToMaster = 0;
    };
    // What was timed since the last take (and forgets it).
    [[nodiscard]] Timing take();

private:
    void run();

    int m_master[2] = {-1, -1}; // pty master fds: [0] the master's end, [1] the device's end
    int m_slave[2] = {-1, -1};  // their slaves, kept open so that the ptys stay up between opens
    int m_wake[2] = {-1, -1};   // a pipe that ends the relay
    QString m_masterName;
    QString m_deviceName;
    qint64 m_characterNs = 0;
    std::thread m_thread;
    std::atomic<bool> m_stopping{false};
    std::mutex m_mutex;
    Timing m_timing;
};

} // namespace mbscope::testpeers
