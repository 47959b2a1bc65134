#include "replay/replayscript.h"

#include "protocol/adubuilder.h"

#include <algorithm>

namespace mbscope {

ReplayScript ReplayScript::read(const QString &path, const CaptureOptions &options)
{
    ReplayScript script;
    script.m_report = ExchangeSource::read(path, options, [&script](const CaptureExchange &e) { script.add(e); });
    return script;
}

void ReplayScript::add(const CaptureExchange &exchange)
{
    if (exchange.kind != CaptureExchange::Kind::Transaction || exchange.transaction.status == TransactionStatus::Late)
        return;
    const AduParts parts = AduBuilder::parse(exchange.transaction.request, exchange.framing);
    if (parts.pdu.isEmpty()) {
        ++m_unusable;
        return;
    }
    ReplayExchange r;
    r.framing = exchange.framing;
    r.unitId = parts.unitId;
    r.requestPdu = parts.pdu;
    r.recorded = exchange.transaction;
    if (m_firstNs < 0)
        m_firstNs = exchange.transaction.sentNs;
    // Requests come in request order; a capture's clock may still step back (another interface,
    // a merged file): pacing never waits a negative time.
    r.offsetNs = std::max<qint64>(0, exchange.transaction.sentNs - m_firstNs);
    if (!m_exchanges.empty())
        r.offsetNs = std::max(r.offsetNs, m_exchanges.back().offsetNs);
    m_statistics.add(r.recorded);
    m_exchanges.push_back(std::move(r));
}

QList<RecordedWrite> ReplayScript::writes() const
{
    QList<RecordedWrite> writes;
    for (size_t i = 0; i < m_exchanges.size(); ++i) {
        if (const auto w = RecordedWrite::of(qsizetype(i), m_exchanges[i].unitId, m_exchanges[i].requestPdu))
            writes.append(*w);
    }
    return writes;
}

QList<quint8> ReplayScript::unitIds() const
{
    QList<quint8> ids;
    for (const ReplayExchange &e : m_exchanges) {
        if (!ids.contains(e.unitId))
            ids.append(e.unitId);
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

} // namespace mbscope
