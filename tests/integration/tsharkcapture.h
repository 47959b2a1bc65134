#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QTemporaryDir>

#include <memory>

namespace mbscope::testpeers {

// One TCP segment with payload seen on the loopback interface.
struct WireSegment {
    qint64 timeNs = 0;     // capture timestamp (the capture's clock: only differences mean anything)
    quint16 sourcePort = 0;
    quint16 destinationPort = 0;
    QByteArray payload;
};

// A tshark capture of one TCP port on the loopback interface, written to a pcapng file and read
// back after it stops. start() returns once tshark says the capture has started (dumpcap has the
// interface open), so nothing sent after it is missed.
class TsharkCapture
{
public:
    TsharkCapture() = default;
    ~TsharkCapture();
    TsharkCapture(const TsharkCapture &) = delete;
    TsharkCapture &operator=(const TsharkCapture &) = delete;

    // False with a reason (for QSKIP) when tshark is missing or cannot capture on lo.
    [[nodiscard]] bool start(quint16 port, int timeoutMs = 30000);
    // Stops the capture (SIGTERM, as Ctrl-C: tshark writes what it has) and reads the segments
    // that carry payload, in capture order.
    [[nodiscard]] bool stopAndRead(QList<WireSegment> *segments, int timeoutMs = 60000);
    [[nodiscard]] const QString &error() const { return m_error; }
    // The pcapng file tshark writes (it exists once start() returned; complete after
    // stopAndRead()); removed with this object.
    [[nodiscard]] const QString &filePath() const { return m_file; }

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<QProcess> m_tshark;
    QString m_file;
    quint16 m_port = 0;
    QString m_error;
};

} // namespace mbscope::testpeers
