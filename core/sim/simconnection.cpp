#include "sim/simconnection.h"

#include <QtCore/QPointer>

#include "protocol/asciiframer.h"
#include "protocol/delimitedframer.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"
#include "sim/simendpoint.h"
#include "sim/simtcpstream.h"
#include "sim/simulator.h"
#include "transport/monotonicclock.h"

#include <QtNetwork/QSslSocket>
#include <QtNetwork/QTcpSocket>

#include <fcntl.h>
#include <utility>

namespace mbscope {

namespace {

std::unique_ptr<StreamFramer> framerFor(const LinkUrl &url)
{
    if (url.delimited.enabled)
        return std::make_unique<DelimitedFramer>(url.delimited);
    switch (url.framing()) {
    case Framing::Rtu: {
        // A request whose CRC fails is dropped whole and the next one read at once, whatever its
        // code (issue 29: a 08/0000 after a bad CRC was lost).
        auto rtu = std::make_unique<RtuFramer>(Direction::Request);
        rtu->setDropsBadFrames(true);
        return rtu;
    }
    case Framing::Ascii: return std::make_unique<AsciiFramer>();
    default: return std::make_unique<MbapFramer>();
    }
}

QString peerOf(const QTcpSocket *socket)
{
    const QString address = socket->peerAddress().toString();
    const QString host = address.contains(QLatin1Char(':')) ? QLatin1Char('[') + address + QLatin1Char(']') : address;
    return host + QLatin1Char(':') + QString::number(socket->peerPort());
}

} // namespace

SimConnection::SimConnection(Simulator *simulator, SimEndpoint *endpoint, QTcpSocket *socket, QObject *parent)
    : QObject(parent)
    , m_simulator(simulator)
    , m_endpoint(endpoint)
    , m_framer(framerFor(endpoint->url()))
    , m_responder(true, this)
    , m_idle(this)
    , m_silence(this)
    , m_peer(peerOf(socket))
    , m_connectedNs(monotonicNowNs())
{
    // Answers are small and must leave at once, not wait for Nagle's algorithm to gather more.
    socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    // A plain TCP connection is read and written on its descriptor (SimTcpStream: a third of the
    // system calls per request); a duplicate of it, so that the QTcpSocket closing its own only
    // drops that reference (no FIN, no RST). TLS stays with QSslSocket.
    const int fd = qobject_cast<QSslSocket *>(socket) == nullptr && socket->socketDescriptor() >= 0
                       ? ::fcntl(int(socket->socketDescriptor()), F_DUPFD_CLOEXEC, 0)
                       : -1;
    if (fd >= 0) {
        socket->abort();
        socket->deleteLater();
        m_stream = new SimTcpStream(fd, this);
        connect(m_stream, &SimTcpStream::readyRead, this, &SimConnection::onReadyRead);
        connect(m_stream, &SimTcpStream::disconnected, this, &SimConnection::onDisconnected);
    } else {
        m_socket = socket;
        socket->setParent(this);
        connect(socket, &QTcpSocket::readyRead, this, &SimConnection::onReadyRead);
        connect(socket, &QTcpSocket::disconnected, this, &SimConnection::onDisconnected);
    }
    m_idle.setSingleShot(true);
    m_silence.setSingleShot(true);
    connect(&m_silence, &QTimer::timeout, this, &SimConnection::onSilence);
    connect(&m_idle, &QTimer::timeout, this, [this] {
        close(QStringLiteral("idle for %1 ms: closed").arg(m_endpoint->options().idleTimeoutMs));
    });
    connect(&m_responder, &SimResponder::closeRequested, this,
            [this](const QString &reason) { close(reason.isEmpty() ? QStringLiteral("closed by a fault rule") : reason); });
    if (m_endpoint->options().idleTimeoutMs > 0)
        m_idle.start(m_endpoint->options().idleTimeoutMs);
    // Bytes may have arrived with the connection (a TLS handshake followed by a request).
    if (m_socket && m_socket->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, &SimConnection::onReadyRead, Qt::QueuedConnection);
}

SimConnection::~SimConnection() = default;

bool SimConnection::isConnected() const
{
    return m_stream ? m_stream->isOpen() : m_socket->state() == QAbstractSocket::ConnectedState;
}

void SimConnection::onReadyRead()
{
    if (m_closing)
        return;
    bool ended = false;
    const QByteArray bytes = m_stream ? m_stream->readAll(&ended) : m_socket->readAll();
    if (!bytes.isEmpty()) {
        if (m_endpoint->options().idleTimeoutMs > 0)
            m_idle.start(m_endpoint->options().idleTimeoutMs);
        m_framer->feed(bytes, monotonicNowNs());
        drain();
        if (!m_closing && m_framer->pendingSize() + m_framer->openSkippedRunSize() > 0)
            m_silence.start(m_endpoint->options().streamSilenceMs);
        else if (m_silence.isActive())
            m_silence.stop();
    }
    // The requests that came before the end are answered first (a client may send its last
    // request and shut its side down).
    if (ended && !m_closing)
        m_stream->closeAfterWrites();
}

void SimConnection::onSilence()
{
    m_framer->flushOnSilence();
    drain();
}

void SimConnection::drain()
{
    // MBAP (Messaging on TCP/IP V1.0b, 3.1.3): a header that is not Modbus's means the stream
    // cannot be trusted any more; the connection is closed once the bytes are reported.
    const bool mbap = m_endpoint->framing() == Framing::Tcp && !m_endpoint->url().delimited.enabled;
    if (mbap && m_framer->openSkippedRunSize() > 0)
        m_framer->flushOnSilence();
    // The lists are kept from one read to the next (StreamFramer::takeOutput): no list is
    // allocated per request.
    QList<StreamFrame> frames = std::exchange(m_frames, {});
    QList<SkippedBytes> skipped = std::exchange(m_skipped, {});
    m_framer->takeOutput(frames, skipped);
    // Frames and skipped runs in stream order.
    qsizetype f = 0;
    qsizetype s = 0;
    while (!m_closing && (f < frames.size() || s < skipped.size())) {
        if (s < skipped.size() && (f >= frames.size() || skipped.at(s).offset < frames.at(f).offset)) {
            m_simulator->noteSkipped(m_endpoint, skipped.at(s), m_peer);
            if (mbap) {
                close(QStringLiteral("invalid MBAP header (protocol id not 0 or length outside 2-254): closed"));
                break;
            }
            ++s;
            continue;
        }
        const StreamFrame &frame = frames.at(f++);
        const qint64 received = frame.lastByteNs != 0 ? frame.lastByteNs : monotonicNowNs();
        QPointer<SimConnection> self(this);
        if (m_simulator->answersLocally(m_endpoint)) {
            // The units answer at once: no sink to build (a std::function allocated per request).
            const FaultPlan plan = m_simulator->handleFrame(m_endpoint, frame.bytes, frame.status, m_peer, received, m_connectedNs);
            if (!self)
                return;
            if (!m_closing)
                enqueue(plan, received);
            continue;
        }
        m_simulator->takeFrame(m_endpoint, frame.bytes, frame.status, m_peer, received, m_connectedNs,
                               [self, received](const FaultPlan &plan) {
                                   if (self && !self->m_closing)
                                       self->enqueue(plan, received);
                               });
    }
    frames.clear();
    skipped.clear();
    m_frames = std::move(frames);
    m_skipped = std::move(skipped);
}

void SimConnection::enqueue(const FaultPlan &plan, qint64 receivedNs)
{
    m_responder.enqueue(plan, receivedNs, [this, id = plan.trafficId](const QByteArray &answer) {
        if (!isConnected())
            return;
        if (m_stream)
            m_stream->write(answer);
        else
            m_socket->write(answer);
        m_simulator->noteSent(m_endpoint, answer, id);
    });
}

void SimConnection::close(const QString &reason)
{
    if (m_closing)
        return;
    m_closing = true;
    m_idle.stop();
    m_silence.stop();
    m_responder.clear();
    m_simulator->noteConnection(m_endpoint, m_peer, SimLogEntry::Verdict::ConnectionClosed, reason);
    if (m_stream && !m_stream->isOpen())
        onDisconnected();
    else if (m_stream)
        m_stream->closeAfterWrites(); // disconnected() follows once written bytes are out
    else if (m_socket->state() == QAbstractSocket::UnconnectedState)
        onDisconnected();
    else
        m_socket->disconnectFromHost(); // disconnected() follows once written bytes are out
}

void SimConnection::onDisconnected()
{
    if (m_finished)
        return;
    m_finished = true;
    if (!m_closing) {
        m_closing = true;
        m_idle.stop();
        m_silence.stop();
        m_responder.clear();
        m_simulator->noteConnection(m_endpoint, m_peer, SimLogEntry::Verdict::ConnectionClosed,
                                    QStringLiteral("closed by the client"));
    }
    Q_EMIT finished(this);
}

} // namespace mbscope

#include "moc_simconnection.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
