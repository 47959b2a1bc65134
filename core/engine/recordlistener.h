#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

struct Transaction;

// Gets each record as soon as EngineCore makes it, by a direct call in the engine's thread
// (EngineCore::addRecordListener): the poller counts a transaction and submits the next request
// without a signal activation in between (issue 3: one per transaction).
class RecordListener
{
public:
    virtual void onRecord(const Transaction &transaction, quint64 tag) = 0;

protected:
    RecordListener() = default;
    ~RecordListener() = default;
    RecordListener(const RecordListener &) = default;
    RecordListener &operator=(const RecordListener &) = default;
};

} // namespace mbscope
