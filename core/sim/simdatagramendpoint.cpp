#include "sim/simdatagramendpoint.h"

#include <QtCore/QPointer>

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
        QPointer<SimDatagramEndpoint> self(this);
        simulator()->takeFrame(this, datagram.data(), FrameStatus::Valid, peer, received, 0,
                               [self, received, address, port](const FaultPlan &plan) {
                                   if (!self)
                                       return;
                                   self->m_responder.enqueue(plan, received, [endpoint = self.data(), address, port,
                                                                              id = plan.trafficId](const QByteArray &answer) {
                                       if (!endpoint->m_socket)
                                           return;
                                       endpoint->m_socket->writeDatagram(answer, address, port);
                                       endpoint->simulator()->noteSent(endpoint, answer, id);
                                   });
                               });
    }
}

} // namespace mbscope

#include "moc_simdatagramendpoint.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
