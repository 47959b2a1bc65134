#pragma once

#include "sim/simendpoint.h"
#include "sim/simresponder.h"

class QUdpSocket;

namespace mbscope {

// udp:// (MBAP) and rtu-udp:// (RTU frames): one datagram is one request, the answer goes back
// to the sender in one datagram (or in several, when a fault plan splits it). Answers to
// different senders run on their own clocks.
class SimDatagramEndpoint final : public SimEndpoint
{
    Q_OBJECT
public:
    SimDatagramEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options);
    ~SimDatagramEndpoint() override;

    bool start(QString *error) override;
    void stop() override;

private:
    void onReadyRead();

    QUdpSocket *m_socket = nullptr;
    SimResponder m_responder;
};

} // namespace mbscope
