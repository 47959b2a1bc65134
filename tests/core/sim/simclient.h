#pragma once

// Plain-socket clients for the simulator's endpoint tests: bytes out, whole frames back, cut by
// mbscope's own framers (the response direction for RTU).

#include "protocol/asciiframer.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"
#include "sim/simendpoint.h"

#include <QtNetwork/QNetworkDatagram>
#include <QtNetwork/QTcpSocket>
#include <QtNetwork/QUdpSocket>
#include <QtTest/QtTest>

#include <memory>
#include <optional>

namespace mbscope::simtest {

constexpr int kWaitMs = 5000;

inline std::unique_ptr<StreamFramer> responseFramer(Framing framing)
{
    switch (framing) {
    case Framing::Rtu: return std::make_unique<RtuFramer>(Direction::Response);
    case Framing::Ascii: return std::make_unique<AsciiFramer>();
    default: return std::make_unique<MbapFramer>();
    }
}

class StreamClient
{
public:
    StreamClient(const SimEndpoint *endpoint)
        : m_framer(responseFramer(endpoint->framing()))
    {
        QObject::connect(&m_socket, &QTcpSocket::readyRead, [this] {
            m_framer->feed(m_socket.readAll());
            for (const StreamFrame &f : m_framer->takeFrames())
                m_frames.append(f.bytes);
        });
        m_socket.connectToHost(QHostAddress::LocalHost, endpoint->boundUrl().port);
    }
    bool waitConnected()
    {
        return QTest::qWaitFor([this] { return m_socket.state() == QAbstractSocket::ConnectedState; }, kWaitMs);
    }
    bool waitDisconnected()
    {
        return QTest::qWaitFor([this] { return m_socket.state() == QAbstractSocket::UnconnectedState; }, kWaitMs);
    }
    void send(const QByteArray &bytes) { m_socket.write(bytes); }
    // The next whole frame, or nothing within the wait.
    std::optional<QByteArray> next(int waitMs = kWaitMs)
    {
        if (!QTest::qWaitFor([this] { return !m_frames.isEmpty(); }, waitMs))
            return std::nullopt;
        return m_frames.takeFirst();
    }
    std::optional<QByteArray> ask(const QByteArray &bytes)
    {
        send(bytes);
        return next();
    }
    [[nodiscard]] int framesWaiting() const { return int(m_frames.size()); }
    QTcpSocket &socket() { return m_socket; }

private:
    QTcpSocket m_socket;
    std::unique_ptr<StreamFramer> m_framer;
    QList<QByteArray> m_frames;
};

class DatagramClient
{
public:
    explicit DatagramClient(const SimEndpoint *endpoint)
        : m_port(endpoint->boundUrl().port)
    {
        m_socket.bind(QHostAddress::LocalHost, 0);
    }
    void send(const QByteArray &bytes) { m_socket.writeDatagram(bytes, QHostAddress::LocalHost, m_port); }
    std::optional<QByteArray> next(int waitMs = kWaitMs)
    {
        if (!QTest::qWaitFor([this] { return m_socket.hasPendingDatagrams(); }, waitMs))
            return std::nullopt;
        return m_socket.receiveDatagram().data();
    }
    std::optional<QByteArray> ask(const QByteArray &bytes)
    {
        send(bytes);
        return next();
    }

private:
    QUdpSocket m_socket;
    quint16 m_port;
};

} // namespace mbscope::simtest
