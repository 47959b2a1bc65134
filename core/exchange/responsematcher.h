#pragma once

#include "requestitem.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QString>

namespace mbscope {

// The keys an answer carries, read without decoding the rest of it.
struct FrameKeys {
    bool valid = false;            // the frame is long enough to carry the keys of its framing
    quint16 transactionId = 0;     // MBAP only
    quint8 unit = 0;
    quint8 functionCode = 0;
};

// Which framed answer belongs to which pending request:
// - MBAP (Modbus TCP and UDP): the transaction id, then the unit id, then the function code
//   (the request's, or the request's with bit 7 set for an exception: V1.1b3, 7);
// - RTU and ASCII, on a serial line or tunnelled over TCP/UDP: the unit id and the function code
//   (a serial line carries one transaction at a time: Serial Line V1.02, 2.1);
// - delimited framing, or a request too short to have keys: the next frame.
// Timing rules (an answer cannot begin before its request was written) belong to the engine.
class ResponseMatcher
{
public:
    enum class Outcome : quint8 {
        Match,
        WrongTransactionId,
        WrongUnit,
        WrongFunction,
        NoKeys, // the frame is too short to carry the keys the request needs
    };
    struct Result {
        Outcome outcome = Outcome::NoKeys;
        QString problem; // empty on Match: which key differs, and what the request expected
        [[nodiscard]] bool matched() const { return outcome == Outcome::Match; }
    };

    [[nodiscard]] static FrameKeys keysOf(QByteArrayView frame, Framing framing);
    [[nodiscard]] static Result match(const RequestItem &request, QByteArrayView frame);
    [[nodiscard]] static Result match(const RequestItem &request, const FrameKeys &keys);
    // Whether the code answers the request's function: the same code, or its exception.
    [[nodiscard]] static bool answersFunction(quint8 requestFunction, quint8 responseFunction);
};

} // namespace mbscope
