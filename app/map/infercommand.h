#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope infer TARGET [--unit N] [--block FC:ADDRESS:COUNT]... [--addresses FIRST-LAST] [--tables LIST]
//                      [--samples N | --duration TIME] [--interval TIME] [--json] [--out FILE [--force]]
// Samples blocks of registers many times (reads only) and proposes for each group of registers a
// type and order, scale, unit and kind, each with a confidence and its evidence. Without --block
// it runs a map scan first and samples the blocks it finds. --out writes a device profile draft.
// Exit 0 when something was sampled, 1 when nothing could be read, 2 for usage or link errors.
int runInfer(const QStringList &arguments);

} // namespace mbscope::app
