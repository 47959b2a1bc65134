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
    return judge(frame.bytes, request);
}

ResponseVerdict::Result ResponseVerdict::judge(const QByteArray &response, const QByteArray &request)
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
