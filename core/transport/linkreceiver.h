#pragma once

#include <QtCore/QByteArray>
#include <QtCore/qglobal.h>

namespace mbscope {

// Takes a link's received bytes and write times by a direct call (Link::setReceiver) instead of
// Link::bytesReceived() and Link::bytesWritten(). The engine lives in its link's thread and gets
// both once per transaction; a signal activation for each was a measurable share of its work per
// transaction (issue 3). Same arguments and same moments as the signals.
class LinkReceiver
{
public:
    virtual void linkBytesReceived(const QByteArray &bytes, qint64 firstByteNs, qint64 lastByteNs) = 0;
    virtual void linkBytesWritten(qint64 lastByteNs) = 0;

protected:
    LinkReceiver() = default;
    ~LinkReceiver() = default;
    LinkReceiver(const LinkReceiver &) = default;
    LinkReceiver &operator=(const LinkReceiver &) = default;
};

} // namespace mbscope
