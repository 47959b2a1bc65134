#pragma once

#include "capture/captureexchange.h"
#include "capture/capturedframe.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// One exchange as a table row, the same columns for CSV and JSON lines:
//   index, kind (transaction, unmatched_response), request_time, response_time (ISO 8601 UTC
//   with nanoseconds, empty when none), latency_us, client, server, framing, unit, function
//   (0x03), function_name, address, quantity, values, status (ok, exception, timeout...),
//   exception (0x02), problem, request_packet, response_packet, request_hex, response_hex.
class ExchangeRow
{
public:
    [[nodiscard]] static QStringList columns();
    // The row's cells in columns() order (CSV: every cell text; empty for none).
    [[nodiscard]] static QStringList cells(const CaptureExchange &exchange, const CaptureConversation *conversation);
    // The same keys as columns(); numbers as numbers, nothing as null.
    [[nodiscard]] static QJsonObject json(const CaptureExchange &exchange, const CaptureConversation *conversation);
    // "2026-11-21T17:54:03.123456789Z"
    [[nodiscard]] static QString isoTime(qint64 ns);
    // A CSV cell: quoted when it holds a comma, a quote or a line break (RFC 4180).
    [[nodiscard]] static QString csvCell(const QString &text);
};

} // namespace mbscope
