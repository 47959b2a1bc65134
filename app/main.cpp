// mbscope-full: the window when run without a subcommand, every headless subcommand otherwise.
// `mbscope` (lightmain.cpp) execs it for what it does not run itself (launcher.h).
#include "commands.h"
#include "plot/histogramplot.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

#ifdef MBSCOPE_HAVE_UI
#include <QtWidgets/QApplication>
#endif

#include <cstdio>
#include <cstring>

int main(int argc, char *argv[])
{
    const char *first = argc > 1 ? argv[1] : nullptr;
    const bool subcommand = first && first[0] != '-' && mbscope::app::isSubcommand(first);
    const bool wantsHelp = first && (std::strcmp(first, "--help") == 0 || std::strcmp(first, "-h") == 0
                                     || std::strcmp(first, "--help-all") == 0 || std::strcmp(first, "--version") == 0
                                     || std::strcmp(first, "help") == 0);
#ifdef MBSCOPE_HAVE_UI
    // poll and sweep draw --histogram with QCustomPlot, a widget: they need a QApplication, on
    // the offscreen platform so that no display is needed (or used) to write a PNG.
    if (subcommand && mbscope::app::HistogramPlot::isRequested(argc, argv)) {
        mbscope::app::HistogramPlot::prepareOffscreenPlatform();
        QApplication app(argc, argv);
        QApplication::setApplicationName(QStringLiteral("mbscope"));
        QApplication::setApplicationVersion(QStringLiteral(MBSCOPE_VERSION));
        return mbscope::app::runHeadless(QCoreApplication::arguments());
    }
#endif
    // A first word that is no subcommand is a typo ("mbscope sned"): say so instead of opening
    // the window.
    const bool unknownWord = first && first[0] != '-' && !subcommand;
    if (subcommand || unknownWord || wantsHelp || !mbscope::app::hasGui()) {
        QCoreApplication app(argc, argv);
        QCoreApplication::setApplicationName(QStringLiteral("mbscope"));
        QCoreApplication::setApplicationVersion(QStringLiteral(MBSCOPE_VERSION));
        return mbscope::app::runHeadless(QCoreApplication::arguments());
    }
#ifdef MBSCOPE_HAVE_UI
    if (mbscope::app::guiWantsOffscreen(argc, argv))
        mbscope::app::HistogramPlot::prepareOffscreenPlatform();
    mbscope::app::takeSessionArgument(argc, argv);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("mbscope"));
    QApplication::setApplicationVersion(QStringLiteral(MBSCOPE_VERSION));
    return mbscope::app::runGui(app);
#else
    return 2;
#endif
}
