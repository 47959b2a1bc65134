#include "responseverdict.h"

#include "protocol/dissector.h"

#include <cstring>

namespace mbscope {

ResponseVerdict::ResponseVerdict(Framing framing, bool delimited)
    : m_framing(framing)
    , m_delimited(delimited)
{
}

ResponseVerdict::Result ResponseVerdict::judge(const StreamFrame &frame, const QByteArray &request)
{
    if (m_delimited) {
        switch (frame.status) {
        case FrameStatus::Valid:
            return Result{};
        case FrameStatus::Malformed:
            return Result{TransactionStatus::CrcError, 0, frame.problem};
        case FrameStatus::Unverified:
        case FrameStatus::Truncated:
            return Result{TransactionStatus::Malformed, 0, frame.problem};
        }
        return Result{TransactionStatus::Malformed, 0, frame.problem};
    }
    if (frame.status == FrameStatus::Truncated) {
        Result cut = judge(frame.bytes, request);
        cut.status = TransactionStatus::Malformed;
        cut.exceptionCode = 0;
        cut.problem = QStringLiteral("the answer was cut short: ") + frame.problem;
        return cut;
    }
    return judge(frame.bytes, request);
}

bool ResponseVerdict::isExpectedRegisterAnswer(QByteArrayView response, QByteArrayView request) const
{
    if (m_delimited || (m_framing != Framing::Tcp && m_framing != Framing::Udp) || request.size() != 12)
        return false;
    const auto *q = reinterpret_cast<const uchar *>(request.data());
    const auto *r = reinterpret_cast<const uchar *>(response.data());
    // The request: MBAP header with protocol id 0 and length 6 (Messaging on TCP/IP V1.0b, 3.1.3),
    // Read Holding or Input Registers of 1 to 125 registers inside the 16-bit address space
    // (V1.1b3, 6.3 and 6.4).
    const int function = q[7];
    const int address = q[8] << 8 | q[9];
    const int quantity = q[10] << 8 | q[11];
    if ((function != 0x03 && function != 0x04) || q[2] != 0 || q[3] != 0 || q[4] != 0 || q[5] != 6 || quantity < 1
        || quantity > 125 || address + quantity > 0x10000)
        return false;
    // The answer: same transaction id and unit, protocol id 0, a length that counts exactly the
    // bytes after it, the same function code and a byte count of two per register asked, with
    // exactly those data bytes. Register values are free.
    return response.size() == 9 + 2 * quantity && r[0] == q[0] && r[1] == q[1] && r[2] == 0 && r[3] == 0
        && (r[4] << 8 | r[5]) == response.size() - 6 && r[6] == q[6] && r[7] == function && r[8] == 2 * quantity;
}

ResponseVerdict::Result ResponseVerdict::judge(const QByteArray &response, const QByteArray &request)
{
    if (m_delimited)
        return Result{};
    if (isExpectedRegisterAnswer(response, request))
        return Result{};
    return judgeByDissection(response, request);
}

ResponseVerdict::Result ResponseVerdict::judgeByDissection(const QByteArray &response, const QByteArray &request)
{
    if (m_delimited)
        return Result{};
    DissectOptions options;
    options.framing = m_framing;
    options.direction = Direction::Response;
    options.request = request;
    Dissector::dissect(response, options, m_dissection);

    const FieldTree &tree = m_dissection.fields;
    int firstError = -1;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &field = tree.at(i);
        if (field.severity != Severity::Error)
            continue;
        if (std::strcmp(field.key, "rtu.crc") == 0 || std::strcmp(field.key, "ascii.lrc") == 0)
            return Result{TransactionStatus::CrcError, 0, field.message};
        if (firstError < 0)
            firstError = i;
    }
    if (firstError >= 0) {
        const Field &field = tree.at(firstError);
        return Result{TransactionStatus::Malformed, 0, QString::fromLatin1(field.key) + QStringLiteral(": ") + field.message};
    }
    const int code = tree.indexOf("modbus.exception_code");
    if (code >= 0 && tree.at(code).length > 0)
        return Result{TransactionStatus::Exception, quint8(tree.at(code).value), QString::fromLatin1(tree.at(code).meaning ? tree.at(code).meaning : "")};
    if (tree.isEmpty())
        return Result{TransactionStatus::Malformed, 0, QStringLiteral("the answer is empty")};
    return Result{};
}

} // namespace mbscope
