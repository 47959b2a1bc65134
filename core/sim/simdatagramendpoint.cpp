#include "sim/simdatagramendpoint.h"

#include "sim/simlisten.h"
#include "sim/simulator.h"
#include "transport/monotonicclock.h"

#include <QtNetwork/QNetworkDatagram>
#include <QtNetwork/QUdpSocket>

namespace mbscope {

SimDatagramEndpoint::SimDatagramEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options)
    : SimEndpoint(simulator, url, options)
    , m_responder(false, this)
{
}

SimDatagramEndpoint::~SimDatagramEndpoint()
{
    stop();
}

bool SimDatagramEndpoint::start(QString *error)
{
    QString why;
    const auto address = listenAddress(url().host, &why);
    if (!address) {
        *error = url().toString() + QStringLiteral(": ") + why;
        return false;
    }
    m_socket = new QUdpSocket(this);
    if (!m_socket->bind(*address, url().port)) {
        *error = url().toString() + QStringLiteral(": ") + m_socket->errorString();
        delete m_socket;
        m_socket = nullptr;
        return false;
    }
    connect(m_socket, &QUdpSocket::readyRead, this, &SimDatagramEndpoint::onReadyRead);
    LinkUrl bound = url();
    bound.port = m_socket->localPort();
    setBound(bound, true);
    return true;
}

void SimDatagramEndpoint::stop()
{
    m_responder.clear();
    if (m_socket)
        m_socket->close();
    setBound(boundUrl(), false);
}

void SimDatagramEndpoint::onReadyRead()
{
    while (m_socket && m_socket->hasPendingDatagrams()) {
        const QNetworkDatagram datagram = m_socket->receiveDatagram();
        const qint64 received = monotonicNowNs();
        if (!datagram.isValid())
            continue;
        const QHostAddress address = datagram.senderAddress();
        const quint16 port = quint16(datagram.senderPort());
        const QString text = address.toString();
        const QString peer = (text.contains(QLatin1Char(':')) ? QLatin1Char('[') + text + QLatin1Char(']') : text)
                             + QLatin1Char(':') + QString::number(port);
        // A datagram holds one whole frame (or it is malformed): no framer, no silence.
        const FaultPlan plan = simulator()->handleFrame(this, datagram.data(), FrameStatus::Valid, peer, received);
        m_responder.enqueue(plan, received, [this, address, port, id = plan.trafficId](const QByteArray &answer) {
            if (!m_socket)
                return;
            m_socket->writeDatagram(answer, address, port);
            simulator()->noteSent(this, answer, id);
        });
    }
}

} // namespace mbscope
