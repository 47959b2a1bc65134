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

QString ProfileLimits::loadProblem(const QByteArray &json, const QString &source)
{
#ifdef MBSCOPE_LIGHT
    Q_UNUSED(json);
    Q_UNUSED(source);
    return QStringLiteral("a device profile is read by mbscope-full, which runs a scan given --profile-out (this copy "
                          "of mbscope started it directly)");
#else
    const ProfileLoadResult loaded = ProfileLoader::parse(json, source);
    return loaded.ok ? QString() : loaded.errorText();
#endif
}

bool ProfileLimits::isRequested(int argc, char *argv[])
{
    if (argc < 2)
        return false;
    const char *option = nullptr;
    if (std::strcmp(argv[1], "poll") == 0 || std::strcmp(argv[1], "sweep") == 0)
        option = "--profile";
    else if (std::strcmp(argv[1], "scan") == 0)
        option = "--profile-out";
    else
        return false;
    const std::size_t length = std::strlen(option);
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--") == 0)
            return false;
        if (std::strncmp(argv[i], option, length) == 0 && (argv[i][length] == '\0' || argv[i][length] == '='))
            return true;
    }
    return false;
}

} // namespace mbscope::app
