#pragma once

#include "capture/captureoptions.h"
#include "capture/exchangesource.h"
#include "exchange/statistics.h"
#include "replay/recordedwrite.h"
#include "replay/replayexchange.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <vector>

namespace mbscope {

// The recorded exchanges of a capture or a traffic journal, in request order: what `mbscope
// replay` re-sends and what its simulator answers with. Read through ExchangeSource, so the
// sources are those analyze reads (pcap, pcapng, journal). Answers that matched no request and
// late answers are left out: they belong to no request to replay.
class ReplayScript
{
public:
    // Reads path; report says what was read (and whether the source was readable at all).
    [[nodiscard]] static ReplayScript read(const QString &path, const CaptureOptions &options);
    // Built from exchanges already read (tests, captures in memory).
    void add(const CaptureExchange &exchange);

    [[nodiscard]] const ExchangeSourceReport &report() const { return m_report; }
    [[nodiscard]] const std::vector<ReplayExchange> &exchanges() const { return m_exchanges; }
    [[nodiscard]] bool isEmpty() const { return m_exchanges.empty(); }
    [[nodiscard]] qsizetype size() const { return qsizetype(m_exchanges.size()); }
    // The recorded transactions' figures (latency: answer time minus request time, as recorded).
    [[nodiscard]] const Statistics &recordedStatistics() const { return m_statistics; }
    // Unit ids the recorded requests address, ascending.
    [[nodiscard]] QList<quint8> unitIds() const;
    // The recorded requests that write to the device (RecordedWrite), in request order.
    [[nodiscard]] QList<RecordedWrite> writes() const;
    // Recorded requests whose bytes could not be taken apart (no unit or function code): left out.
    [[nodiscard]] quint64 unusable() const { return m_unusable; }

private:
    ExchangeSourceReport m_report;
    std::vector<ReplayExchange> m_exchanges;
    Statistics m_statistics;
    qint64 m_firstNs = -1;
    quint64 m_unusable = 0;
};

} // namespace mbscope
