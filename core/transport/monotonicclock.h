#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// Nanoseconds from CLOCK_MONOTONIC: never jumps with wall-clock changes, comparable across
// threads of one process. Every timestamp of the engine and the links comes from here.
[[nodiscard]] qint64 monotonicNowNs();
// What to add to a wall-clock time (nanoseconds since the epoch: a capture's packets, a journal
// read back) to place it on the monotonic clock as it stands now, so that recorded and live
// frames share one time line (CLOCK_MONOTONIC minus CLOCK_REALTIME, read together).
[[nodiscard]] qint64 wallToMonotonicOffsetNs();

} // namespace mbscope
