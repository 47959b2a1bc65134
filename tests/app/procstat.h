#pragma once

#include <QtCore/QtGlobal>

namespace mbscope::testcli {

// A running process's figures from /proc (proc(5)), for the benchmarks and the soaks.

// CPU seconds (user + system) the process has used so far; withChildren adds those of the children
// it has waited for (cutime, cstime: socat's forks). -1 when /proc/PID/stat cannot be read.
[[nodiscard]] double processCpuSeconds(qint64 pid, bool withChildren = false);

// Its resident memory now (VmRSS in /proc/PID/status), in KiB; -1 when it cannot be read.
[[nodiscard]] qint64 processRssKiB(qint64 pid);

} // namespace mbscope::testcli
