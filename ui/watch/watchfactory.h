#pragma once

#include "profile/deviceprofile.h"
#include "protocol/framing.h"
#include "watch/watchdefinition.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

namespace mbscope {

struct WatchFromRequest {
    WatchDefinition watch;
    QString error; // empty when watch is usable
};

// Watches made from what the window already has: the composer's read request (its unit,
// function, address and quantity), or a device profile's unit (a watch per group of entries of
// one table that a single read can cover; an entry longer than a read is cut into consecutive
// watches, none of it left out; no watch asks more than the profile's limits.maxQuantity of its
// function). Names are made unique against the ones taken.
class WatchFactory
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::WatchFactory)

public:
    // Reads a request can hold: 125 registers, 2000 bits (V1.1b3 6.1-6.4).
    static constexpr int kMaxRegisters = 125;
    static constexpr int kMaxBits = 2000;
    // Entries this far apart (addresses) still share one read: fewer requests, a few unused words.
    static constexpr int kMaxGap = 8;

    // adu: the composer's bytes in framing. Only reads (01-04, FIFO 18) make a watch.
    [[nodiscard]] static WatchFromRequest fromRequest(const QByteArray &adu, Framing framing, const QString &target,
                                                      qint64 intervalMs, const QStringList &taken);
    [[nodiscard]] static QList<WatchDefinition> fromProfile(const DeviceProfile &profile, quint8 unit,
                                                            const QString &target, qint64 intervalMs,
                                                            const QStringList &taken);
    // base, or "base 2", "base 3"... whichever is not taken.
    [[nodiscard]] static QString uniqueName(const QString &base, const QStringList &taken);
    // "holding 0x0079 x22" for a watch without a name of its own.
    [[nodiscard]] static QString describeBlock(quint8 function, quint16 address, quint16 quantity);
};

} // namespace mbscope
