#pragma once

#include "profile/devicelimits.h"

#include <QtCore/QString>

#include <optional>

namespace mbscope::app {

// The limits of a device profile for poll and sweep --profile. Loading a profile checks all of
// it, scripts included (QJSEngine), so it runs in mbscope-full: `mbscope` hands a poll with
// --profile over (Launcher::needsFull), and its own copy of this file only refuses.
class ProfileLimits
{
public:
    // A shipped profile's name or a JSON file; nullopt with *error saying what is wrong and where.
    [[nodiscard]] static std::optional<DeviceLimits> load(const QString &nameOrPath, QString *error);
    // The arguments ask for it: poll or sweep with --profile (before any "--").
    [[nodiscard]] static bool isRequested(int argc, char *argv[]);
};

} // namespace mbscope::app
