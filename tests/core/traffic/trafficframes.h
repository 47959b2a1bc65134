#pragma once

// Frames for the traffic log and journal tests: frame n has every field derived from n, so a
// reader can check each frame it gets back.
#include "traffic/trafficlog.h"

#include <QtCore/QLocale>

namespace mbscope::testing {

struct Made {
    qint64 tNs;
    TrafficDirection direction;
    TrafficVerdict verdict;
    quint64 transactionId;
    QByteArray bytes;
};

inline Made made(quint64 n, int size = -1)
{
    const int length = size >= 0 ? size : int(n % 37);
    QByteArray bytes(length, Qt::Uninitialized);
    for (int i = 0; i < length; ++i)
        bytes[i] = char((n * 31 + quint64(i) * 7) & 0xFF);
    return {qint64(n) * 1000 + 17, n % 2 ? TrafficDirection::In : TrafficDirection::Out,
            TrafficVerdict(n % kTrafficVerdictCount), n / 2 + 1, bytes};
}

inline quint64 appendMade(TrafficLog &log, quint16 link, quint64 n, int size = -1)
{
    const Made m = made(n, size);
    return log.append(m.tNs, m.direction, link, m.verdict, m.transactionId, m.bytes);
}

inline bool matches(const TrafficEntry &e, quint64 n, int size = -1)
{
    const Made m = made(n, size);
    return e.sequence == n && e.tNs == m.tNs && e.direction == m.direction && e.verdict == m.verdict
        && e.transactionId == m.transactionId && e.bytes == QByteArrayView(m.bytes);
}

// Numbers as the journal's messages write them: 12,000.
inline QString grouped(qint64 n)
{
    return QLocale(QLocale::English, QLocale::UnitedStates).toString(n);
}

} // namespace mbscope::testing
