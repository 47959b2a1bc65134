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

TrafficSearch::TrafficSearch(const QString &query, const TrafficLinks &links)
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
    const QStringList &names = links.names();
    m_linkMatches.resize(size_t(names.size()));
    for (qsizetype i = 0; i < names.size(); ++i)
        m_linkMatches[size_t(i)] = contains(names.at(i));
}

bool TrafficSearch::matches(const TrafficEntry &frame, const FrameKeys &keys) const
{
    if (m_empty)
        return false;
    if (m_verdictMatches[size_t(frame.verdict)])
        return true;
    if (keys.valid && m_functionMatches[keys.functionCode])
        return true;
    if (frame.link < m_linkMatches.size() && m_linkMatches[frame.link])
        return true;
    const QByteArrayView bytes = frame.bytes;
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
