#pragma once

#include "framing.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QString>

namespace mbscope {

// MODBUS over Serial Line V1.02, 2.1: on a serial framing (RTU, ASCII, also carried over TCP or
// UDP) a request to unit 0 is a broadcast: every server acts on it and none answers, so broadcast
// requests are writes only. A read, or any function whose point is its answer, sent to unit 0
// can never return anything. On Modbus/TCP (MBAP) unit 0 is no broadcast: it addresses the
// server or gateway itself (Messaging on TCP/IP V1.0b, 4.4.1.1).
class BroadcastRule
{
public:
    // Whether a request with this function code is made for its answer: the reads (01-04, 07,
    // 0B, 0C, 11, 14, 17, 18, 2B). Writes (05, 06, 0F, 10, 15, 16), Diagnostics (08, whose
    // restart and listen-only sub-functions are broadcast on purpose) and codes the spec does not
    // define are not.
    [[nodiscard]] static bool wantsAnswer(quint8 functionCode);
    // Why a request with this function code to unit 0 cannot be answered.
    [[nodiscard]] static QString readProblem(quint8 functionCode);
    // Whether adu, a request in framing, is a read broadcast on a serial framing (unit 0).
    [[nodiscard]] static bool isBroadcastRead(QByteArrayView adu, Framing framing);
    // readProblem() for adu when it is a read broadcast on a serial framing; empty otherwise.
    [[nodiscard]] static QString broadcastReadProblem(QByteArrayView adu, Framing framing);
};

} // namespace mbscope
