#pragma once

#include "peerprocess.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QProcessEnvironment>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>

namespace mbscope::testcli {

// What one run of the mbscope executable left.
struct CliResult {
    bool finished = false; // within the time allowed (else it was killed)
    int exitCode = -1;
    QByteArray out;
    QByteArray err;

    [[nodiscard]] QString outText() const { return QString::fromUtf8(out); }
    [[nodiscard]] QString errText() const { return QString::fromUtf8(err); }
    // Standard output parsed as a JSON object (empty when it is not one).
    [[nodiscard]] QJsonObject json() const;
    // For failure messages: exit status and both streams.
    [[nodiscard]] QByteArray describe() const;
};

// The mbscope executable under test (the build's, passed in by CMake).
[[nodiscard]] QString mbscopePath();

// Runs mbscope with arguments and waits for it (killed after timeoutMs). env: the test's own by default.
[[nodiscard]] CliResult runMbscope(const QStringList &arguments, int timeoutMs = 120000,
                                   const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment());

// A pymodbus server (tests/peers/pymodbus_server.py) in one mode ("tcp", "udp", "rtu-tcp",
// "ascii-tcp"), on a port it chooses, stopped when the object goes.
class PymodbusTarget
{
public:
    [[nodiscard]] bool start(const QString &mode, QString *error);
    // "tcp://127.0.0.1:PORT"
    [[nodiscard]] QString url() const { return m_url; }
    [[nodiscard]] bool isRunning() const { return m_peer && m_peer->isRunning(); }

private:
    std::unique_ptr<testpeers::PeerProcess> m_peer;
    QString m_url;
};

// A port on 127.0.0.1 where nothing listens: bound by the OS's choice, then released.
[[nodiscard]] quint16 closedPort();

// Big-endian registers in hex ("03E8 03EB") from the peers' data map (peer_datamap.h).
[[nodiscard]] quint16 holdingRegister(int address);
[[nodiscard]] quint16 inputRegister(int address);
[[nodiscard]] bool coil(int address);

} // namespace mbscope::testcli
