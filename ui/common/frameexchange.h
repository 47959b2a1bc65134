#pragma once

#include "exchange/trafficentry.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// One frame picked in the traffic monitor, with what belongs with it: the request it answers (or
// the answer it got), the link's framing and the latency. It is what the decode view shows, so a
// selection in the traffic list and a transaction from the engine reach it the same way.
struct FrameExchange {
    QByteArray request;  // bytes out; empty when the frame is an answer to no known request
    QByteArray response; // bytes in; empty when there was none (timeout, still waiting)
    Framing framing = Framing::Auto; // the link's framing (Auto: detect from the bytes)
    TrafficDirection selected = TrafficDirection::Out; // which of the two was picked
    TrafficVerdict verdict = TrafficVerdict::Sent;     // the exchange's verdict so far
    qint64 latencyNs = -1;     // request to answer, as latencyToEnd says; -1: none
    // What latencyNs measures. false (a frame of the traffic list): from the request's write to
    // the answer's first byte, as the recording keeps them. true (a transaction of the link, as
    // the Analysis dock and the poll's figures count): from the request sent (a serial line: its
    // last byte on the line) to the answer's last byte.
    bool latencyToEnd = false;
    quint64 transactionId = 0; // Transaction::id, 0 for frames of no transaction
    QString link;              // the link's URL, empty when unknown

    [[nodiscard]] bool hasRequest() const { return !request.isEmpty(); }
    [[nodiscard]] bool hasResponse() const { return !response.isEmpty(); }
    // The bytes of the picked frame.
    [[nodiscard]] const QByteArray &selectedBytes() const
    {
        return selected == TrafficDirection::Out ? request : response;
    }
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::FrameExchange)
