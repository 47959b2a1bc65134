#include "trafficentry.h"

#include <array>

namespace mbscope {

namespace {

constexpr std::array<const char *, kTrafficVerdictCount> kVerdictNames{
    "ok",         "exception", "timeout", "crc_error", "malformed",   "unexpected",
    "link_error", "broadcast", "late",    "sent",      "unsolicited", "garbage",
};

} // namespace

TrafficVerdict trafficVerdict(TransactionStatus status)
{
    switch (status) {
    case TransactionStatus::Ok: return TrafficVerdict::Ok;
    case TransactionStatus::Exception: return TrafficVerdict::Exception;
    case TransactionStatus::Timeout: return TrafficVerdict::Timeout;
    case TransactionStatus::CrcError: return TrafficVerdict::CrcError;
    case TransactionStatus::Malformed: return TrafficVerdict::Malformed;
    case TransactionStatus::Unexpected: return TrafficVerdict::Unexpected;
    case TransactionStatus::LinkError: return TrafficVerdict::LinkError;
    case TransactionStatus::Broadcast: return TrafficVerdict::Broadcast;
    case TransactionStatus::Late: return TrafficVerdict::Late;
    }
    return TrafficVerdict::Unexpected;
}

const char *trafficVerdictName(TrafficVerdict verdict)
{
    const auto index = std::size_t(verdict);
    return index < kVerdictNames.size() ? kVerdictNames[index] : "unknown";
}

TrafficVerdict trafficVerdictFromName(QAnyStringView name, bool *known)
{
    for (std::size_t i = 0; i < kVerdictNames.size(); ++i) {
        if (QAnyStringView::equal(name, QLatin1String(kVerdictNames[i]))) {
            if (known)
                *known = true;
            return TrafficVerdict(i);
        }
    }
    if (known)
        *known = false;
    return TrafficVerdict::Garbage;
}

const char *trafficDirectionName(TrafficDirection direction)
{
    return direction == TrafficDirection::In ? "in" : "out";
}

TrafficFrame TrafficFrame::from(const TrafficEntry &entry)
{
    return {entry.sequence, entry.tNs, entry.transactionId, entry.link, entry.direction, entry.verdict,
            entry.bytes.toByteArray()};
}

} // namespace mbscope
