#include "poll/sweepcommand.h"

#include "poll/pollcommand.h"

namespace mbscope::app {

int runSweep(const QStringList &arguments)
{
    return runPollOrSweep(arguments, true);
}

} // namespace mbscope::app
