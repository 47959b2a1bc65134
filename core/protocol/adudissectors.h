#pragma once

#include "dissection.h"

#include <QtCore/QByteArray>

// The ADU layers of the dissector: each appends the framing's own fields around the PDU's.
// Internal to core/protocol; Dissector is the public entry.
namespace mbscope::adu {

// What is known of the matching request once its own ADU has been taken apart.
struct RequestInfo {
    QByteArrayView pdu;  // function code first; empty when no request was given. Views the
                         // caller's request bytes (or storage, for ASCII): no copy per frame.
    QByteArray storage;  // owns decoded bytes when the request had to be decoded (ASCII)
    int unit = -1;       // unit id, -1 when unknown
    int transactionId = -1; // MBAP only
};

[[nodiscard]] RequestInfo requestInfo(const QByteArray &request, Framing framing);

// frameCrc: the CRC-16/MODBUS of all the frame's bytes but the last two when the caller has
// computed it already (framing detection does), -1 to have it computed.
void dissectRtu(Dissection &out, const RequestInfo &request, int frameCrc = -1);
void dissectMbap(Dissection &out, const RequestInfo &request);
void dissectAscii(Dissection &out, const RequestInfo &request);
void dissectBarePdu(Dissection &out, const RequestInfo &request);

// ASCII frames carry hex digits; this turns ":0703...2A\r\n" into the binary unit, PDU and LRC.
// On failure returns false and sets error to what is wrong and at which character.
[[nodiscard]] bool decodeAsciiPayload(const QByteArray &frame, QByteArray &binary, QString *error, int *errorOffset);

} // namespace mbscope::adu
