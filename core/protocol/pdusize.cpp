#include "pdusize.h"

// Size rules of every public function code, from the PDU layouts of the MODBUS Application
// Protocol Specification V1.1b3, section 6. Sizes count the function code.
//
// Choices:
// - A size is reported as the bytes announce it, even above the 253-byte PDU limit (V1.1b3, 4.1):
//   the dissector needs it to say how many bytes are missing, and the RTU framer checks the limit.
// - Exception responses (code >= 0x80) are always 2 bytes (V1.1b3, 7). As a request such a code is
//   impossible: Unknown.
// - 08 sub-function 00 (Return Query Data) echoes data of any length, so it has no size rule:
//   Unknown (the RTU framer then waits for the silence). So do the reserved sub-functions.
// - 2B/0D (CANopen General Reference) and other MEI types carry data of unspecified length: Unknown.
// - Direction::Auto: exception codes are responses; otherwise both directions are computed and the
//   answer is given only when they agree (e.g. 05, 06, 16, or NeedMore while the code alone is
//   seen); when they disagree the result is Unknown, because the caller must choose a direction.

namespace mbscope::pdusize {

namespace {

constexpr Expected complete(int size) { return {Status::Complete, size}; }
constexpr Expected needMore(int size) { return {Status::NeedMore, size}; }
constexpr Expected unknown() { return {Status::Unknown, 0}; }

quint8 byteAt(QByteArrayView pdu, int index) { return quint8(pdu[index]); }

// A PDU whose byte at countOffset counts the bytes that follow it.
Expected byteCounted(QByteArrayView pdu, int countOffset)
{
    if (pdu.size() <= countOffset)
        return needMore(countOffset + 1);
    return complete(countOffset + 1 + byteAt(pdu, countOffset));
}

// V1.1b3, 6.8.1: the standard sub-functions all carry one 16-bit data word each way.
bool isFixedDiagnostic(quint16 subFunction)
{
    return (subFunction >= 0x01 && subFunction <= 0x04) || (subFunction >= 0x0A && subFunction <= 0x12)
        || subFunction == 0x14;
}

Expected diagnostics(QByteArrayView pdu)
{
    if (pdu.size() < 3)
        return needMore(3);
    const quint16 subFunction = quint16(byteAt(pdu, 1) << 8 | byteAt(pdu, 2));
    return isFixedDiagnostic(subFunction) ? complete(5) : unknown();
}

// V1.1b3, 6.21: function code, MEI type, read device id code, conformity level, more follows,
// next object id, number of objects, then per object: id, length, value.
Expected deviceIdentificationResponse(QByteArrayView pdu)
{
    constexpr int headerSize = 7;
    if (pdu.size() < headerSize)
        return needMore(headerSize);
    const int objectCount = byteAt(pdu, 6);
    int position = headerSize;
    for (int object = 0; object < objectCount; ++object) {
        if (pdu.size() < position + 2)
            return needMore(position + 2);
        position += 2 + byteAt(pdu, position + 1);
    }
    return complete(position);
}

Expected encapsulated(QByteArrayView pdu, Direction direction)
{
    if (pdu.size() < 2)
        return needMore(2);
    if (byteAt(pdu, 1) != 0x0E)
        return unknown();
    return direction == Direction::Request ? complete(4) : deviceIdentificationResponse(pdu);
}

Expected request(QByteArrayView pdu)
{
    switch (byteAt(pdu, 0)) {
    case 0x01: case 0x02: case 0x03: case 0x04: case 0x05: case 0x06:
        return complete(5); // address/start + quantity/value (6.1-6.6)
    case 0x07: case 0x0B: case 0x0C: case 0x11:
        return complete(1); // function code only (6.7, 6.9, 6.10, 6.13)
    case 0x08:
        return diagnostics(pdu);
    case 0x0F: case 0x10:
        return byteCounted(pdu, 5); // start, quantity, byte count (6.11, 6.12)
    case 0x14: case 0x15:
        return byteCounted(pdu, 1); // byte count of the sub-requests (6.14, 6.15)
    case 0x16:
        return complete(7); // address, AND mask, OR mask (6.16)
    case 0x17:
        return byteCounted(pdu, 9); // read start/quantity, write start/quantity, byte count (6.17)
    case 0x18:
        return complete(3); // FIFO pointer address (6.18)
    case 0x2B:
        return encapsulated(pdu, Direction::Request);
    default:
        return unknown();
    }
}

Expected response(QByteArrayView pdu)
{
    const quint8 code = byteAt(pdu, 0);
    if (code >= 0x80)
        return complete(2); // function code + 0x80, exception code (7)
    switch (code) {
    case 0x01: case 0x02: case 0x03: case 0x04: case 0x0C: case 0x11: case 0x14: case 0x15: case 0x17:
        return byteCounted(pdu, 1);
    case 0x05: case 0x06: case 0x0F: case 0x10:
        return complete(5); // echo of address/start and value/quantity (6.5, 6.6, 6.11, 6.12)
    case 0x07:
        return complete(2); // output data (6.7)
    case 0x08:
        return diagnostics(pdu);
    case 0x0B:
        return complete(5); // status, event count (6.9)
    case 0x16:
        return complete(7); // echo of the request (6.16)
    case 0x18:
        // Byte count is 16 bits and counts the FIFO count and values that follow it (6.18).
        if (pdu.size() < 3)
            return needMore(3);
        return complete(3 + (byteAt(pdu, 1) << 8 | byteAt(pdu, 2)));
    case 0x2B:
        return encapsulated(pdu, Direction::Response);
    default:
        return unknown();
    }
}

} // namespace

Expected expectedPduSize(QByteArrayView pdu, Direction direction)
{
    if (pdu.isEmpty())
        return needMore(1);
    switch (direction) {
    case Direction::Request:
        return request(pdu);
    case Direction::Response:
        return response(pdu);
    case Direction::Auto:
        break;
    }
    if (byteAt(pdu, 0) >= 0x80)
        return response(pdu);
    const Expected asRequest = request(pdu);
    const Expected asResponse = response(pdu);
    if (asRequest.status == asResponse.status && asRequest.size == asResponse.size)
        return asRequest;
    return unknown();
}

} // namespace mbscope::pdusize
