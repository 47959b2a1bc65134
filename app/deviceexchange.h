#pragma once

#include "exchange/transaction.h"

#include <QtCore/QList>

namespace mbscope::app {

struct PlannedRequest;
struct TargetSettings;

// Sends requests one after the other through a TransactionEngine and waits for each record
// (send, read and write). Stops after a link error: nothing more would reach the device.
[[nodiscard]] QList<Transaction> exchange(const TargetSettings &target, const QList<PlannedRequest> &requests);

} // namespace mbscope::app
