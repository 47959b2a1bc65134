#include "fieldlocator.h"

namespace mbscope {

int FieldLocator::depth(const FieldTree &tree, int field)
{
    int d = 0;
    // Parents come before children (FieldTree is depth-first), so the walk always ends.
    for (int p = tree.at(field).parent; p >= 0 && p < field; p = tree.at(p).parent)
        ++d;
    return d;
}

int FieldLocator::innermostField(const FieldTree &tree, int offset, int length)
{
    const qint64 first = offset;
    const qint64 end = first + qMax(1, length);
    int best = -1;
    int bestDepth = -1;
    qint32 bestLength = 0;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        // A field about missing bytes covers nothing: it cannot be picked from the bytes.
        if (f.length <= 0 || f.offset > first || qint64(f.offset) + f.length < end)
            continue;
        const int d = depth(tree, i);
        if (d > bestDepth || (d == bestDepth && f.length < bestLength)) {
            best = i;
            bestDepth = d;
            bestLength = f.length;
        }
    }
    return best;
}

} // namespace mbscope
