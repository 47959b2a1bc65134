#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QJsonObject>
#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

class JsonReader;

// Reads the watches of a session document (docs/session.schema.json, version 2): the keys
// "watches" (an array of watches), "watchLinks" (settings of the links they name) and "watchLog"
// (CSV logging) of the document's top-level object. Every problem goes to the JsonReader with the
// JSON path of the value at fault ("watches[2].rules[0].forPolls: 0 is below 1") and what was
// expected; unknown keys are refused. A watch:
//
//   {"name": "gamma", "target": "rtu-tcp://127.0.0.1:4001", "unit": 1, "function": 3,
//    "address": "0x0079", "quantity": 14, "intervalMs": 500,
//    "points": [{"address": "0x0079", "name": "high voltage", "unit": "V"},
//               {"address": "0x0086", "name": "counts", "format": "u16", "scale": 1,
//                "bitFields": [{"name": "overflow", "bits": 15}, {"name": "mode", "bits": "8-11",
//                               "states": ["off", "count", "hold"]}]}],
//    "rules": [{"point": "counts", "above": 300, "forPolls": 3, "severity": "alarm"}]}
//
// A rule has exactly one condition key: "above": N, "below": N, "outside": [low, high],
// "inside": [low, high], "equal": N, "notEqual": N or "bits": mask.
class WatchReader
{
public:
    // The three keys of root, each optional.
    [[nodiscard]] static SessionWatches read(JsonReader &reader, const QJsonObject &root);
    // One watch at path ("watches[2]"); nullopt when it is not an object. Names are not checked
    // against other watches here.
    [[nodiscard]] static std::optional<WatchDefinition> readWatch(JsonReader &reader, const QJsonValue &value,
                                                                  const QString &path);
    // Whether key is one of the keys this reader reads from a document's top level.
    [[nodiscard]] static bool isWatchKey(const QString &key);
};

} // namespace mbscope
