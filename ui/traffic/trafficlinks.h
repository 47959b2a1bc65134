#pragma once

#include "exchange/responsematcher.h"
#include "exchange/trafficentry.h"
#include "protocol/framing.h"

#include <QtCore/QString>
#include <QtCore/QStringList>

#include <vector>

namespace mbscope {

// The links of the traffic list by id (TrafficEntry::link), each with its URL and the framing the
// URL gives, so that a frame's unit and function code are read as the engine reads them
// (ResponseMatcher::keysOf). A link with no URL known is read by the frame's look: an MBAP
// header, a ':' (ASCII), else RTU.
class TrafficLinks
{
public:
    void setName(quint16 link, const QString &url);
    // The id of a link by URL, added when new.
    [[nodiscard]] quint16 idOf(const QString &url);
    [[nodiscard]] QString name(quint16 link) const;
    [[nodiscard]] Framing framing(quint16 link) const; // Auto when the link is not named
    [[nodiscard]] const QStringList &names() const { return m_names; }

    // Unit and function code of a frame on its link; not valid for a delimited protocol's frames
    // (no unit, no function) or a frame too short to carry them.
    [[nodiscard]] FrameKeys keysOf(const TrafficEntry &entry) const;

    [[nodiscard]] std::size_t memoryBytes() const;

private:
    QStringList m_names; // by link id; empty: not named
    std::vector<Framing> m_framings;
    std::vector<bool> m_delimited;
};

} // namespace mbscope
