#include "jobend.h"

namespace mbscope {

const char *jobEndName(JobEnd end)
{
    switch (end) {
    case JobEnd::Completed: return "completed";
    case JobEnd::Stopped: return "stopped";
    case JobEnd::TimeLimit: return "time_limit";
    case JobEnd::LinkError: return "link_error";
    case JobEnd::RequestLimit: return "request_limit";
    }
    return "completed";
}

} // namespace mbscope
