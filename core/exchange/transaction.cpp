#include "transaction.h"

namespace mbscope {

QString transactionStatusName(TransactionStatus status)
{
    switch (status) {
    case TransactionStatus::Ok: return QStringLiteral("ok");
    case TransactionStatus::Exception: return QStringLiteral("exception");
    case TransactionStatus::Timeout: return QStringLiteral("timeout");
    case TransactionStatus::CrcError: return QStringLiteral("crc_error");
    case TransactionStatus::Malformed: return QStringLiteral("malformed");
    case TransactionStatus::Unexpected: return QStringLiteral("unexpected");
    case TransactionStatus::LinkError: return QStringLiteral("link_error");
    case TransactionStatus::Broadcast: return QStringLiteral("broadcast");
    case TransactionStatus::Late: return QStringLiteral("late");
    }
    return QStringLiteral("unknown");
}

} // namespace mbscope
