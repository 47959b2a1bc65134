#pragma once

#include "engine/engineprogress.h"
#include "exchange/requestitem.h"
#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <functional>
#include <optional>

namespace mbscope {
class TransactionEngine;
}

namespace mbscope::testpeers {

// A target URL the test wrote itself; an unparsable one is a bug in the test (qFatal).
[[nodiscard]] LinkUrl targetUrl(const QString &text);
// A network target on 127.0.0.1: "tcp", "udp", "rtu-tcp", "ascii-tcp".
[[nodiscard]] LinkUrl networkTarget(const QString &scheme, quint16 port);
// A serial target at 115200 8N1 (the pty ignores the rate, but t1.5/t3.5 follow from it).
[[nodiscard]] LinkUrl serialTarget(const QString &scheme, const QString &device);

// The request ADU for a PDU on the URL's framing (MBAP header with the transaction id, or RTU
// CRC, or ASCII LRC), as a RequestItem with the keys the engine matches on.
[[nodiscard]] RequestItem request(const LinkUrl &url, const QByteArray &pdu, quint8 unit = 1,
                                  quint16 transactionId = 1, int timeoutMs = 2000);
// The PDU of a transaction's response (function code first), taken out of its framing.
[[nodiscard]] QByteArray responsePdu(const Transaction &t, Framing framing);

// Expected answers computed from the peers' data map (peer_datamap.h).
[[nodiscard]] QByteArray expectedReadBits(quint8 functionCode, int start, int quantity);
[[nodiscard]] QByteArray expectedReadRegisters(quint8 functionCode, int start, int quantity);
[[nodiscard]] QByteArray hex(const char *text); // "01 03 00 00" -> bytes

// "ok", or "timeout: no answer within 2000 ms" for failure messages.
[[nodiscard]] QString describe(const Transaction &t);
[[nodiscard]] QString describe(const std::optional<Transaction> &t);
// "sent 150, in 1850 bytes, unsolicited 1 (duplicates 1), late 0, skipped 0 bytes, ..."
[[nodiscard]] QString describe(const EngineCounters &c);

// Watches an engine: every record it delivers (late ones included) and the latest counters.
class EngineProbe : public QObject
{
    Q_OBJECT
public:
    explicit EngineProbe(TransactionEngine *engine);

    [[nodiscard]] const QList<Transaction> &records() const { return m_records; }
    [[nodiscard]] const EngineCounters &counters() const { return m_counters; }
    // Runs the event loop until the condition holds or timeoutMs passes; returns the condition.
    bool waitFor(const std::function<bool()> &condition, int timeoutMs);
    // The latest record with this id and status, if one came.
    [[nodiscard]] std::optional<Transaction> find(quint64 id, TransactionStatus status) const;

private:
    QList<Transaction> m_records;
    EngineCounters m_counters;
};

} // namespace mbscope::testpeers
