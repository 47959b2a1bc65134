#include "launcher.h"

#include "common/cli.h"
#include "commands.h"
#include "plot/histogramplot.h"
#include "poll/profilelimits.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <initializer_list>

#include <unistd.h>

namespace mbscope::app {

namespace {

bool isOneOf(const char *word, std::initializer_list<const char *> words)
{
    for (const char *w : words) {
        if (std::strcmp(word, w) == 0)
            return true;
    }
    return false;
}

} // namespace

bool Launcher::needsFull(int argc, char *argv[])
{
    if (argc < 2)
        return true; // the window
    const char *first = argv[1];
    if (first[0] == '-')
        return !isOneOf(first, {"--help", "-h", "--version"}); // the window's options, --help-all
    if (std::strcmp(first, "help") == 0) // `help NAME`: NAME's --help, where NAME runs
        return argc > 2 && isSubcommand(argv[2]) && !runsHere(argv[2]);
    if (!isSubcommand(first))
        return false; // a typo that the dispatcher names
    if (!runsHere(first))
        return true;
    return HistogramPlot::isRequested(argc, argv) || ProfileLimits::isRequested(argc, argv);
}

std::string Launcher::fullPath()
{
    char self[4096];
    const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (length <= 0)
        return "mbscope-full";
    std::string path(self, std::size_t(length));
    const std::size_t slash = path.rfind('/');
    return path.substr(0, slash + 1) + "mbscope-full";
}

int Launcher::execFull(char *argv[])
{
    const std::string path = fullPath();
    ::execv(path.c_str(), argv);
    const int error = errno;
    std::fprintf(stderr,
                 "mbscope: cannot start %s, the part of mbscope with the window, the simulator, the watch service "
                 "and the plots: %s (it is installed beside mbscope; reinstall the package or rebuild)\n",
                 path.c_str(), std::strerror(error));
    return ExitUsage;
}

} // namespace mbscope::app
