#include "trafficsearch.h"

#include "common/coretext.h"

#include "protocol/functioncode.h"
#include "protocol/hextext.h"

namespace mbscope {

namespace {

char lower(char c)
{
    return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c;
}

} // namespace

TrafficSearch::TrafficSearch(const QString &query, const TrafficStore &store)
    : m_store(store)
{
    const QString text = query.trimmed();
    m_empty = text.isEmpty();
    if (m_empty)
        return;
    const HexTextResult hex = HexText::parse(text);
    if (hex.ok)
        m_hex = hex.bytes;
    m_latin = text.toLower().toLatin1();
    const auto contains = [&text](const QString &s) { return s.contains(text, Qt::CaseInsensitive); };
    for (int v = 0; v < kTrafficVerdictCount; ++v)
        m_verdictMatches[size_t(v)] = contains(QLatin1String(trafficVerdictName(TrafficVerdict(v))));
    for (int code = 0; code < 256; ++code)
        m_functionMatches[size_t(code)] = contains(QLatin1String(functionName(quint8(code)))) || contains(fieldText(functionName(quint8(code))));
    const QStringList &links = store.linkNames();
    m_linkMatches.resize(size_t(links.size()));
    for (qsizetype i = 0; i < links.size(); ++i)
        m_linkMatches[size_t(i)] = contains(links.at(i));
}

bool TrafficSearch::matches(qsizetype storeRow) const
{
    if (m_empty)
        return false;
    const TrafficStore::Row &r = m_store.row(storeRow);
    if (m_verdictMatches[size_t(r.verdict)])
        return true;
    if (r.hasFunction() && m_functionMatches[r.function])
        return true;
    if (r.link < m_linkMatches.size() && m_linkMatches[r.link])
        return true;
    const QByteArrayView bytes = m_store.bytes(storeRow);
    if (!m_hex.isEmpty() && bytes.indexOf(m_hex) >= 0)
        return true;
    // As characters, case-insensitive: ASCII frames are hex digits in either case.
    if (bytes.size() < m_latin.size())
        return false;
    const char first = m_latin.at(0);
    for (qsizetype i = 0; i + m_latin.size() <= bytes.size(); ++i) {
        if (lower(bytes[i]) != first)
            continue;
        qsizetype k = 1;
        while (k < m_latin.size() && lower(bytes[i + k]) == m_latin.at(k))
            ++k;
        if (k == m_latin.size())
            return true;
    }
    return false;
}

} // namespace mbscope
