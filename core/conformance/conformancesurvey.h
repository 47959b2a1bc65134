#pragma once

#include "conformancecheck.h"
#include "conformancelink.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

class ConformanceContext;

// Before the checks: one harmless read of every function the battery may use (01-04 at the
// readable address, 07, 08/00 return query data, 0B, 0C, 11, 2B/0E basic identification), so
// that support is read from the device's answers (exception 01: not supported; an answer or any
// other exception: supported; nothing: silent) and checks of what it does not support are skipped.
// A request the link dropped under is asked again on a new connection; a function the device
// could still not be asked about (not even sent) is NotSurveyed, and its checks are skipped.
// Its checks judge the survey itself: silence instead of exception 01, and a profile's promise.
class ConformanceSurvey
{
public:
    struct Outcome {
        bool linkFailed = false; // the first request found no device (refused, no such host or port)
        bool silent = false;     // no request of the survey was answered at all
        QString message;
        QList<ConformanceExchange> exchanges;
    };
    [[nodiscard]] static Outcome run(ConformanceContext &context);
    [[nodiscard]] static QList<ConformanceCheck> checks();
    // The functions surveyed, in order.
    [[nodiscard]] static QList<quint8> functions();
};

} // namespace mbscope
