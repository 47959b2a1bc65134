#pragma once

#include "faultrule.h"

#include <QtCore/QJsonObject>

namespace mbscope {

// Fault rules written back in the shape FaultRuleReader reads (docs/profiles.md, "Fault
// injection"): a faults file {"seed": ..., "rules": [...]} or one rule. Only what differs from
// what the reader assumes for a missing key is written, so a written rule reads as it was
// given. What is read back equals what was written (FaultRule's ==).
class FaultRuleWriter
{
public:
    [[nodiscard]] static QJsonObject toJson(const FaultRule &rule);
    [[nodiscard]] static QJsonObject toJson(const FaultRuleSet &set);
};

} // namespace mbscope
