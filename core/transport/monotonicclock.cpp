#include "monotonicclock.h"

#include <time.h>

namespace mbscope {

qint64 monotonicNowNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return qint64(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

qint64 wallToMonotonicOffsetNs()
{
    timespec real{};
    timespec mono{};
    clock_gettime(CLOCK_REALTIME, &real);
    clock_gettime(CLOCK_MONOTONIC, &mono);
    return (qint64(mono.tv_sec) - qint64(real.tv_sec)) * 1000000000LL + (mono.tv_nsec - real.tv_nsec);
}

} // namespace mbscope
