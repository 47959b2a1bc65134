#pragma once

#include "profile/devicelimits.h"

#include <QtCore/QString>

#include <optional>

namespace mbscope::app {

// The limits of a device profile for poll and sweep --profile, and the check of a profile that
// scan --profile-out merges into. Loading a profile checks all of it, scripts included (QJSEngine),
// so it runs in mbscope-full: `mbscope` hands such a poll or scan over (Launcher::needsFull), and
// its own copy of this file only refuses.
class ProfileLimits
{
public:
    // A shipped profile's name or a JSON file; nullopt with *error saying what is wrong and where.
    [[nodiscard]] static std::optional<DeviceLimits> load(const QString &nameOrPath, QString *error);
    // What keeps a profile's JSON text (from source, a path) from loading as the simulator loads
    // it, every problem with where it is; empty when it loads.
    [[nodiscard]] static QString loadProblem(const QByteArray &json, const QString &source);
    // The arguments ask for it: poll or sweep with --profile, scan with --profile-out (before any
    // "--").
    [[nodiscard]] static bool isRequested(int argc, char *argv[]);
};

} // namespace mbscope::app
