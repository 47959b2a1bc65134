#pragma once

#include "protocol/framing.h"
#include "sim/simreply.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <functional>

namespace mbscope {

// What answers an endpoint's requests when it is not the simulator's own units: a responder that
// takes a request and answers it when it can, later (the inline tap's TapForwarder sends it on to
// a real device and answers with what the device said). Simulator::setRemote puts one behind
// every endpoint; the simulator still checks each frame first (checksum, MBAP header: a broken
// frame is never forwarded), logs both directions, runs its fault hook over the answer and writes
// it through the endpoint, so an answer from a real device is recorded and can be disturbed like
// one of the simulator's.
class SimRemote
{
public:
    struct Request {
        quint8 unitId = 0;
        QByteArray pdu;        // function code first, as received
        Framing framing = Framing::Tcp; // of the endpoint it came in on
        bool broadcast = false; // unit 0 on a serial framing (Serial Line V1.02, 2.1): nobody answers
        QString endpoint;       // the endpoint's URL as bound
        QString peer;           // "127.0.0.1:53122", a serial device
        qint64 receivedNs = 0;  // monotonicNowNs() when the request's last byte arrived
    };
    struct Answer {
        SimReply reply;     // Silent: no answer (reply.note says why)
        // When set, sent exactly as it is instead of reply.pdu framed for the endpoint: the
        // device's own bytes where both sides speak the same serial framing.
        QByteArray exactAdu;
    };
    // Called once per request, at once or later, in the simulator's thread.
    using Done = std::function<void(const Answer &answer)>;

    virtual ~SimRemote() = default;
    virtual void forward(const Request &request, Done done) = 0;

protected:
    SimRemote() = default;
    SimRemote(const SimRemote &) = default;
    SimRemote &operator=(const SimRemote &) = default;
};

} // namespace mbscope
