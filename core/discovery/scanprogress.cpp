#include "scanprogress.h"

namespace mbscope {

const char *scanEndName(ScanEnd end)
{
    switch (end) {
    case ScanEnd::Completed: return "completed";
    case ScanEnd::Stopped: return "stopped";
    case ScanEnd::TimeLimit: return "time_limit";
    case ScanEnd::LinkError: return "link_error";
    case ScanEnd::RequestLimit: return "request_limit";
    }
    return "completed";
}

} // namespace mbscope
