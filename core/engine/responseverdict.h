#pragma once

#include "transaction.h"

#include "protocol/dissection.h"
#include "protocol/streamframe.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// The status of a matched answer, decided by the Dissector reading it as the response to its
// request (DissectOptions{framing, Direction::Response, request}):
// - a wrong CRC (rtu.crc) or LRC (ascii.lrc): CrcError, whatever else is wrong, since a damaged
//   frame's other fields cannot be trusted;
// - any other error (byte count against the data, MBAP length, missing or trailing bytes, a
//   quantity that does not echo the request...): Malformed, with the first error said;
// - otherwise an exception function code (bit 7 set): Exception with its code (V1.1b3, 7);
// - otherwise Ok. Warnings and notes do not change the status.
// Delimited frames carry no Modbus: the framer's status decides (a bad checksum is a CrcError).
// One instance per engine: the Dissection is reused, so a verdict allocates nothing on valid frames.
class ResponseVerdict
{
public:
    struct Result {
        TransactionStatus status = TransactionStatus::Ok;
        quint8 exceptionCode = 0;
        QString problem;
    };

    ResponseVerdict(Framing framing, bool delimited);

    [[nodiscard]] Result judge(const StreamFrame &frame, const QByteArray &request);
    [[nodiscard]] Result judge(const QByteArray &response, const QByteArray &request);
    // The last dissection made by judge() (fields of the answer, for observers that show them).
    [[nodiscard]] const Dissection &lastDissection() const { return m_dissection; }

private:
    Framing m_framing;
    bool m_delimited;
    Dissection m_dissection;
};

} // namespace mbscope
