#include "watchchangefilter.h"

namespace mbscope {

bool WatchChangeFilter::changed(const WatchSample &sample)
{
    const auto it = m_last.find(sample.watch);
    if (it != m_last.end() && it->status == sample.status && it->exceptionCode == sample.exceptionCode &&
        it->words == sample.words && it->bits == sample.bits)
        return false;
    m_last.insert(sample.watch, Last{sample.status, sample.exceptionCode, sample.words, sample.bits});
    return true;
}

} // namespace mbscope
