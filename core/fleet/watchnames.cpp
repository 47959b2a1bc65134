#include "watchlinkstate.h"
#include "watchsample.h"

namespace mbscope {

QString watchSampleStatusName(WatchSample::Status status)
{
    switch (status) {
    case WatchSample::Status::Ok: return QStringLiteral("ok");
    case WatchSample::Status::Exception: return QStringLiteral("exception");
    case WatchSample::Status::Timeout: return QStringLiteral("timeout");
    case WatchSample::Status::CrcError: return QStringLiteral("crc_error");
    case WatchSample::Status::Error: return QStringLiteral("error");
    }
    return {};
}

QString watchLinkStateName(WatchLinkState::State state)
{
    switch (state) {
    case WatchLinkState::State::Connecting: return QStringLiteral("connecting");
    case WatchLinkState::State::Up: return QStringLiteral("up");
    case WatchLinkState::State::Down: return QStringLiteral("down");
    case WatchLinkState::State::Backoff: return QStringLiteral("backoff");
    case WatchLinkState::State::Stopped: return QStringLiteral("stopped");
    }
    return {};
}

} // namespace mbscope
