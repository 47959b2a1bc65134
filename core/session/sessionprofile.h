#pragma once

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {

// The device profile a session uses (register names, types, scaling; docs/profiles.md): none,
// a reference to a shipped profile by name ("rosrao-gamma") or to a user profile file (a path,
// relative to the session document), or the profile itself inline.
struct SessionProfile {
    enum class Kind : quint8 { None, Reference, Inline };
    Kind kind = Kind::None;
    QString reference;
    QJsonObject profile; // Inline: the profile document as docs/profile.schema.json describes it

    friend bool operator==(const SessionProfile &, const SessionProfile &) = default;
};

} // namespace mbscope
