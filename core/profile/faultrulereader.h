#pragma once

#include "delayspec.h"
#include "faultrule.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

class JsonReader;

// Reads delays and fault rules from JSON (the "faults" object of a profile, a faults file),
// recording problems in the reader. Formats in docs/profiles.md.
class FaultRuleReader
{
public:
    // A delay: a number (fixed milliseconds) or {"distribution": "normal", "meanMs": 4, ...}.
    [[nodiscard]] static std::optional<DelaySpec> readDelay(JsonReader &reader, const QJsonValue &value,
                                                            const QString &path);
    [[nodiscard]] static std::optional<FaultRule> readRule(JsonReader &reader, const QJsonValue &value,
                                                           const QString &path);
    // {"seed": 7, "rules": [...]}; the seed defaults to defaultSeed.
    [[nodiscard]] static FaultRuleSet readRuleSet(JsonReader &reader, const QJsonValue &value, const QString &path,
                                                  quint64 defaultSeed);
};

} // namespace mbscope
