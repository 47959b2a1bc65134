#pragma once

#include "protocol/dissection.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {

// What the decode view's Copy puts on the clipboard, for a request and its answer (either may be
// missing). Text and JSON are DissectionFormat's, so a copy reads like `mbscope decode`.
class ExchangeFormat
{
public:
    struct Exchange {
        const Dissection *request = nullptr;  // null or empty: none
        const Dissection *response = nullptr; // null or empty: none
        qint64 latencyNs = -1;                // -1: unknown
        QString verdict;                      // trafficVerdictName, empty when unknown
    };

    // "Request" and "Response" headings over DissectionFormat::toTable, then the latency.
    [[nodiscard]] static QString toText(const Exchange &exchange);
    // {"request": {...}, "response": {...}, "latency_ns": n, "verdict": "ok"}: absent parts left out.
    [[nodiscard]] static QJsonObject toJson(const Exchange &exchange);
    // One line of spaced hex per frame, request first.
    [[nodiscard]] static QString toHex(const Exchange &exchange);
    // "12.345 ms", "850 µs"; empty for -1.
    [[nodiscard]] static QString latencyText(qint64 ns);
};

} // namespace mbscope
