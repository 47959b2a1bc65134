#pragma once

#include "exchange/transaction.h"
#include "replay/answercomparison.h"

namespace mbscope {

// One recorded request replayed: what came back now and how it compares with what was recorded.
struct ReplayOutcome {
    qsizetype index = 0;   // in the ReplayScript
    Transaction replayed;  // as the engine recorded it now
    AnswerComparison::Result comparison;
};

} // namespace mbscope
