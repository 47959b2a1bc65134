#include "exchange/deviceexchange.h"

#include "common/framelog.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"

#include "engine/transactionengine.h"

namespace mbscope::app {

QList<Transaction> exchange(const TargetSettings &target, const QList<PlannedRequest> &requests, TrafficLog *log,
                            FrameLog *frames)
{
    TransactionEngine engine;
    engine.setTarget(target.url);
    if (log)
        engine.setTrafficLog(log);
    if (frames)
        frames->attach(&engine);
    QList<Transaction> records;
    for (const PlannedRequest &r : requests) {
        std::optional<Transaction> t = engine.sendAndWait(r.item);
        if (!t) {
            // sendAndWait waits for every timeout and retry plus the connect timeout and a margin:
            // getting here means the engine lost the request, which is a bug to report as it is.
            Transaction lost;
            lost.request = r.item.bytes;
            lost.status = TransactionStatus::LinkError;
            lost.problem = QStringLiteral("the engine recorded nothing for this request (a bug in mbscope)");
            t = lost;
        }
        records.append(*t);
        if (t->status == TransactionStatus::LinkError)
            break;
    }
    if (log)
        engine.setTrafficLog(nullptr); // the last frames reach the journal
    if (frames)
        engine.deliverPending(); // and the frame log
    return records;
}

} // namespace mbscope::app
