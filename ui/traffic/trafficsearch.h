#pragma once

#include "trafficlinks.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <array>
#include <vector>

namespace mbscope {

// What "find" in the traffic monitor matches. Text that reads as hex ("01 03 00 79") finds frames
// containing those bytes; any text also finds rows whose verdict, function name or link contains it
// (case-insensitive), and frames whose bytes contain it as characters (ASCII framing, delimited
// protocols). The words are matched against the few verdicts, 256 codes and links once, so testing
// a row is table look-ups and one byte search: a million rows are searched in well under a second.
class TrafficSearch
{
public:
    TrafficSearch(const QString &query, const TrafficLinks &links);

    [[nodiscard]] bool isEmpty() const { return m_empty; }
    [[nodiscard]] bool isHex() const { return !m_hex.isEmpty(); }
    // A frame with its unit and function code (for an empty frame in: its request's).
    [[nodiscard]] bool matches(const TrafficEntry &frame, const FrameKeys &keys) const;

private:
    QByteArray m_hex;   // the query as bytes, when it reads as hex
    QByteArray m_latin; // the query as characters, lower case
    std::array<bool, kTrafficVerdictCount> m_verdictMatches{};
    std::array<bool, 256> m_functionMatches{};
    std::vector<bool> m_linkMatches;
    bool m_empty = true;
};

} // namespace mbscope
