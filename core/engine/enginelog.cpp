#include "enginecore.h"

namespace mbscope {

void EngineCore::logOutgoing(const QByteArray &bytes, qint64 ns)
{
    Q_UNUSED(bytes);
    Q_UNUSED(ns);
}

void EngineCore::logIncoming(const QByteArray &bytes, qint64 firstNs, qint64 lastNs, const QString &verdict)
{
    Q_UNUSED(bytes);
    Q_UNUSED(firstNs);
    Q_UNUSED(lastNs);
    Q_UNUSED(verdict);
}

void EngineCore::logTransaction(const Transaction &transaction)
{
    Q_UNUSED(transaction);
}

} // namespace mbscope
