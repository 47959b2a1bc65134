#include "poll/profilelimits.h"

#ifndef MBSCOPE_LIGHT
#include "profile/profileloader.h"
#endif

#include <cstring>

namespace mbscope::app {

std::optional<DeviceLimits> ProfileLimits::load(const QString &nameOrPath, QString *error)
{
#ifdef MBSCOPE_LIGHT
    *error = QStringLiteral("a device profile is read by mbscope-full, which runs a poll given --profile (this copy "
                            "of mbscope started it directly)");
    Q_UNUSED(nameOrPath);
    return std::nullopt;
#else
    const ProfileLoadResult loaded = ProfileLoader::load(nameOrPath);
    if (!loaded.ok) {
        *error = loaded.errorText();
        return std::nullopt;
    }
    return loaded.profile.limits;
#endif
}

bool ProfileLimits::isRequested(int argc, char *argv[])
{
    if (argc < 2 || (std::strcmp(argv[1], "poll") != 0 && std::strcmp(argv[1], "sweep") != 0))
        return false;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--") == 0)
            return false;
        if (std::strcmp(argv[i], "--profile") == 0 || std::strncmp(argv[i], "--profile=", 10) == 0)
            return true;
    }
    return false;
}

} // namespace mbscope::app
