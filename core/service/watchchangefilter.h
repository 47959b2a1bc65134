#pragma once

#include "fleet/watchsample.h"

#include <QtCore/QHash>
#include <QtCore/QList>

namespace mbscope {

// Tells whether a poll differs from the last one of its watch that was let through: its status
// (and exception code), its registers or its bits. The service's "on change" publishing; one
// entry per watch, so memory stays bounded however long it runs.
class WatchChangeFilter
{
public:
    [[nodiscard]] bool changed(const WatchSample &sample);
    void clear() { m_last.clear(); }

private:
    struct Last {
        WatchSample::Status status = WatchSample::Status::Timeout;
        quint8 exceptionCode = 0;
        QList<quint16> words;
        QList<bool> bits;
    };
    QHash<int, Last> m_last;
};

} // namespace mbscope
