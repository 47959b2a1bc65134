#pragma once

#include "script/scriptsettings.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

class JsonReader;

// A unit's (or a delimited table's) "script": a file name beside the profile, or
// {"file": ..., "tickMs": ..., "timeoutMs": ..., "onError": "exception"|"silence"|"answer"}.
// The file is loaded once in a throwaway engine (ScriptHost::check), so a syntax error is the
// profile's problem, located in the script: "units[1].script: gamma.js:12:5: SyntaxError: ...".
class ScriptSettingsReader
{
public:
    [[nodiscard]] static std::optional<ScriptSettings> read(JsonReader &reader, const QJsonValue &value, const QString &path);
};

} // namespace mbscope
