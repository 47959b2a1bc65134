#pragma once

#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

namespace mbscope {

class SimRandom;

// The exact wire bytes of the faults that change an answer's content. Each alters only what the
// fault names: the other fields stay consistent (lengths, byte counts, checksums recomputed), so
// a client sees exactly one thing wrong. Every function returns an empty array when the fault
// does not apply to the bytes given (then the answer is sent unchanged).
class FaultBytes
{
public:
    // RTU: both CRC bytes inverted; ASCII: the LRC inverted (its two hex digits rewritten).
    // Nothing for MBAP framings, which carry no checksum.
    [[nodiscard]] static QByteArray wrongChecksum(QByteArrayView adu, Framing framing);
    // MBAP: transaction id + delta (modulo 2^16). Nothing for serial framings.
    [[nodiscard]] static QByteArray wrongTransactionId(QByteArrayView adu, Framing framing, int delta);
    // The unit id + delta (modulo 256), checksum recomputed.
    [[nodiscard]] static QByteArray wrongUnit(QByteArrayView adu, Framing framing, int delta);
    // The exception response to function with code (V1.1b3 7), in the answer's framing, unit and
    // transaction id.
    [[nodiscard]] static QByteArray exception(QByteArrayView adu, Framing framing, quint8 function, quint8 code);
    // A read answer `fewer` registers short (01/02: data bytes short), byte count (and FIFO count)
    // consistent with the data, checksum or MBAP length recomputed: only the quantity is wrong.
    // Nothing for exceptions, other functions, or answers that hold no data.
    [[nodiscard]] static QByteArray fewerRegisters(QByteArrayView adu, Framing framing, int fewer);
    // The PDU alone: 01/02 bytes, 03/04/17 registers, 18 FIFO registers removed from the end.
    [[nodiscard]] static QByteArray fewerRegistersPdu(QByteArrayView pdu, int fewer);

    // The ADU rebuilt around a new PDU and unit, with the transaction and protocol id of adu.
    // Line noise: each bit of bytes flipped with probability bitErrorRate, drawn from random (as
    // sent: a CRC, LRC or BCC is not recomputed, so it fails as it would on a noisy line).
    [[nodiscard]] static QByteArray flipBits(QByteArrayView bytes, double bitErrorRate, SimRandom &random);
    [[nodiscard]] static QByteArray rewrap(QByteArrayView adu, Framing framing, QByteArrayView pdu, quint8 unit);
};

} // namespace mbscope
