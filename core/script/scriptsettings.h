#pragma once

#include <QtCore/QString>

namespace mbscope {

// A unit's script as its profile names it ("script": {"file": ..., ...}, docs/profiles.md).
struct ScriptSettings {
    enum class OnError : quint8 {
        Exception, // exception 04 (server device failure, V1.1b3 7)
        Silence,   // no answer
        Normal,    // the profile's answer, as if the script had not spoken
    };
    QString path;            // where the file is read from (beside the profile, or ":/profiles/...")
    QString name;            // as the profile names it ("counter.js"): errors and logs say this
    double tickMs = 0;       // onTick(time) this often; 0: never
    double timeoutMs = 100;  // a call running longer is interrupted
    OnError onError = OnError::Exception; // after a call threw or was interrupted

    [[nodiscard]] bool isEmpty() const { return path.isEmpty(); }

    friend bool operator==(const ScriptSettings &, const ScriptSettings &) = default;
};

} // namespace mbscope
