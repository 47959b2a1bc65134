#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QtGlobal>

namespace mbscope {

// Why a job ended. Every end but Completed keeps what the job got until then (a stopped scan's
// map holds the blocks found before Stop).
enum class JobEnd : quint8 {
    Completed, // every step done
    Stopped,   // cancelled (Ctrl-C, the Stop button, Esc)
    TimeLimit, // the job's time limit passed first
    LinkError, // the link failed: nothing more can be learnt through it
    RequestLimit, // the job's request limit was reached first
};

[[nodiscard]] const char *jobEndName(JobEnd end); // "completed", "stopped", "time_limit", "link_error", "request_limit"

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::JobEnd)
