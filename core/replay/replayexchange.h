#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>

namespace mbscope {

// One recorded request and its recorded outcome, as replay needs it: the request taken apart
// (unit and PDU, so it can be re-framed for another link or matched whatever the MBAP
// transaction id), and the recorded Transaction (status, answer bytes, capture times).
struct ReplayExchange {
    Framing framing = Framing::Tcp; // of the recorded request and answer
    quint8 unitId = 0;
    QByteArray requestPdu;          // function code first
    qint64 offsetNs = 0;            // recorded request time minus the first request's
    Transaction recorded;

    [[nodiscard]] bool recordedAnswer() const { return !recorded.response.isEmpty(); }
};

} // namespace mbscope
