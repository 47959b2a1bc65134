#include "widevaluelayout.h"

#include <algorithm>

namespace mbscope {

QList<WideValueLayout::Value> WideValueLayout::lay(int address, int count, int width, const EntryAt &entryAt)
{
    QList<Value> rows(std::max(count, 0));
    width = std::max(width, 1);
    const auto entry = [&entryAt](int at) { return entryAt ? entryAt(at) : std::nullopt; };
    int r = 0;
    while (r < count) {
        const std::optional<Entry> here = entry(address + r);
        // On the entry's grid (the answer may begin inside one of its values), else from here.
        const int start = here ? r - (address + r - here->address) % width : r;
        int end = std::min(start + width, count);
        // A value stops where another profile value begins: the profile's layout wins.
        for (int q = r + 1; q < end; ++q) {
            const std::optional<Entry> next = entry(address + q);
            const bool sameEntry = next && here && next->address == here->address;
            if (next && !sameEntry) {
                end = q;
                break;
            }
        }
        for (int i = r; i < end; ++i)
            rows[i] = {start, end};
        r = end;
    }
    return rows;
}

} // namespace mbscope
