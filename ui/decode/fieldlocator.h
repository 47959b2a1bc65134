#pragma once

#include "protocol/fieldtree.h"

namespace mbscope {

// Between fields and bytes: which field a run of bytes belongs to. Kept apart from the views so
// the rule ("the innermost field that covers every picked byte") is tested on its own.
class FieldLocator
{
public:
    // The deepest field whose span holds [offset, offset + length) (length 0 counts as 1); among
    // fields of the same depth the shortest, then the first. -1 when no field covers it.
    [[nodiscard]] static int innermostField(const FieldTree &tree, int offset, int length = 1);
    // The field's depth: 0 at the top.
    [[nodiscard]] static int depth(const FieldTree &tree, int field);
};

} // namespace mbscope
