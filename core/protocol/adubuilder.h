#pragma once

#include "framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

namespace mbscope {

// How an outgoing PDU is wrapped when the user asks for completion.
struct AduOptions {
    Framing framing = Framing::Rtu; // Tcp and Udp both get an MBAP header; Pdu and Auto leave bytes alone
    quint8 unitId = 1;
    quint16 transactionId = 0; // MBAP only
    quint16 protocolId = 0;    // MBAP only: 0 is Modbus; anything else is sent on purpose
};

// Whether bytes the user gives are a whole ADU (sent exactly as given, a wrong CRC included) or a
// PDU that must be completed into an ADU. Completion never happens unless asked for.
enum class Completion : quint8 {
    AsGiven,
    CompletePdu,
};

// An ADU taken apart, nothing changed. Fields that the framing does not have stay at their defaults.
struct AduParts {
    Framing framing = Framing::Pdu;
    bool complete = false; // the bytes hold the framing's whole structure; else error says what is missing
    QString error;         // empty when complete and well formed
    quint8 unitId = 0;
    QByteArray pdu;        // function code first; as much as is present

    // MBAP (Tcp, Udp)
    quint16 transactionId = 0;
    quint16 protocolId = 0;
    quint16 length = 0;    // the header's length field as received
    bool lengthMatches = false; // length == unit id + PDU bytes present

    // RTU (CRC-16, as a number: low byte first on the wire) and ASCII (LRC)
    bool checksumPresent = false;
    quint16 checksum = 0;         // as received
    quint16 expectedChecksum = 0; // computed over the unit id and the PDU
    [[nodiscard]] bool checksumValid() const { return checksumPresent && checksum == expectedChecksum; }
};

// Completing PDUs into ADUs and taking ADUs apart, for every framing:
// MBAP (MODBUS Messaging on TCP/IP V1.0b, 3.1.3), RTU (MODBUS over Serial Line V1.02, 2.5.1) and
// ASCII (Serial Line V1.02, 2.5.2). RTU over TCP/UDP use the RTU layout; Modbus UDP uses MBAP.
class AduBuilder
{
public:
    // MBAP header (transaction id, protocol id, length = 1 + PDU size, unit id) then the PDU. A PDU
    // longer than 65534 bytes cannot be described; its length field is clamped to 0xFFFF.
    [[nodiscard]] static QByteArray mbap(QByteArrayView pdu, quint8 unitId, quint16 transactionId,
                                         quint16 protocolId = 0);
    // Unit id, PDU, CRC-16/MODBUS low byte first.
    [[nodiscard]] static QByteArray rtu(QByteArrayView pdu, quint8 unitId);
    // ':' then unit id, PDU and LRC as uppercase hex digits, then CR LF.
    [[nodiscard]] static QByteArray ascii(QByteArrayView pdu, quint8 unitId);

    // The PDU completed as the options say; for Framing::Pdu and Framing::Auto the PDU as it is.
    [[nodiscard]] static QByteArray complete(QByteArrayView pdu, const AduOptions &options);
    // What goes on the wire: bytes as given, or the PDU completed. AsGiven never changes a byte.
    [[nodiscard]] static QByteArray outgoing(QByteArrayView bytes, Completion completion,
                                             const AduOptions &options);

    [[nodiscard]] static AduParts parseMbap(QByteArrayView adu);
    [[nodiscard]] static AduParts parseRtu(QByteArrayView adu);
    // The whole frame, ':' to LF. Non-hex characters or an odd digit count leave complete false
    // and pdu holding the bytes decoded before the first bad character.
    [[nodiscard]] static AduParts parseAscii(QByteArrayView adu);
    // Tcp/Udp: parseMbap; Rtu: parseRtu; Ascii: parseAscii; Pdu/Auto: the bytes as a bare PDU.
    [[nodiscard]] static AduParts parse(QByteArrayView adu, Framing framing);

    // Hex digit value, or -1; shared with the ASCII framer.
    [[nodiscard]] static int hexDigitValue(char c);
};

} // namespace mbscope
