#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// Nanoseconds from CLOCK_MONOTONIC: never jumps with wall-clock changes, comparable across
// threads of one process. Every timestamp of the engine and the links comes from here.
[[nodiscard]] qint64 monotonicNowNs();

} // namespace mbscope
