#pragma once

#include "exchange/transaction.h"

#include <QtCore/QList>

namespace mbscope {
class TrafficLog;
}

namespace mbscope::app {

class FrameLog;
struct PlannedRequest;
struct TargetSettings;

// Sends requests one after the other through a TransactionEngine and waits for each record
// (send, read and write). Stops after a link error: nothing more would reach the device. Every
// frame goes to log when there is one (--record), and to frames as it comes (--print frames).
[[nodiscard]] QList<Transaction> exchange(const TargetSettings &target, const QList<PlannedRequest> &requests,
                                          TrafficLog *log = nullptr, FrameLog *frames = nullptr);

} // namespace mbscope::app
