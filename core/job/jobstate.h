#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QtGlobal>

namespace mbscope {

// Where a job is in its life: Idle before its first run, Running, Stopping once cancelled (its
// work ends at the next step, keeping what it got), Finished with an end reason (JobEnd).
enum class JobState : quint8 { Idle, Running, Stopping, Finished };

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::JobState)
