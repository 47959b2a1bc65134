#pragma once
// Replay and plan results travel from the runners' threads to the GUI's in queued signals: their
// metatypes are declared once, before any header whose signals carry them.

#include "replay/replayoutcome.h"
#include "replay/replayresult.h"
#include "session/planresult.h"

#include <QtCore/QMetaType>

Q_DECLARE_METATYPE(mbscope::ReplayOutcome)
Q_DECLARE_METATYPE(mbscope::ReplayResult)
Q_DECLARE_METATYPE(mbscope::StepResult)
Q_DECLARE_METATYPE(mbscope::PlanResult)
