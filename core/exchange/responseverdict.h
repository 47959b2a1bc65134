#pragma once

#include "transaction.h"

#include "protocol/dissection.h"
#include "protocol/streamframe.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
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
// - an RTU frame the silence cut before the length its function code predicts (FrameStatus::
//   Truncated): Malformed, "the answer was cut short: ...", though its CRC fails too, since what
//   the line did was lose its end (the bus monitor says the same of the same answer);
// Delimited frames carry no Modbus: the framer's status decides (a bad checksum is a CrcError).
// One instance per engine: the Dissection is reused, so a verdict allocates nothing on valid frames.
//
// The common poll, Read Holding or Input Registers over MBAP (tcp, udp), is checked first without
// building the field tree: an answer that has exactly the header, function code, byte count and
// length the request asks for is Ok (every byte but the register values is compared; the
// dissector has nothing more to say about such an answer, tst_responseverdict checks that they
// agree on every one-byte change). Any other answer, and every other function and framing, is
// dissected in full, which also says what is wrong.
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
    // The last dissection made by judge() (fields of the answer, for observers that show them);
    // an answer found Ok by the register check above leaves it as it was.
    [[nodiscard]] const Dissection &lastDissection() const { return m_dissection; }
    // judge() without the register check: always through the dissector.
    [[nodiscard]] Result judgeByDissection(const QByteArray &response, const QByteArray &request);
    // True when response is exactly the answer a Read Holding/Input Registers request over MBAP
    // asks for (then judge() says Ok without dissecting); false says nothing either way.
    [[nodiscard]] bool isExpectedRegisterAnswer(QByteArrayView response, QByteArrayView request) const;

private:
    Framing m_framing;
    bool m_delimited;
    Dissection m_dissection;
};

} // namespace mbscope
