#pragma once

// The dispatcher: which subcommand runs, or the window. What subcommands share is cli.h.
// commands.cpp is compiled into both executables, `mbscope` (MBSCOPE_LIGHT) and mbscope-full.

#include "common/cli.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#ifdef MBSCOPE_HAVE_UI
class QApplication;
#endif

namespace mbscope::app {

[[nodiscard]] bool isSubcommand(const char *name);
// Whether this executable runs the subcommand itself: every one in mbscope-full; in `mbscope`
// (built with MBSCOPE_LIGHT) the light ones, the others are handed to mbscope-full (launcher.h).
[[nodiscard]] bool runsHere(const char *name);

// Every subcommand with its --help text, in the order `mbscope --help` lists them.
[[nodiscard]] QList<SubcommandHelp> subcommandHelps();
// The options `mbscope` takes without a subcommand that runHeadless answers (--help...).
[[nodiscard]] QStringList topLevelOptions();
[[nodiscard]] bool hasGui();
// Runs a subcommand (or prints help); arguments as QCoreApplication::arguments() gives them.
int runHeadless(const QStringList &arguments);
#ifdef MBSCOPE_HAVE_UI
int runGui(QApplication &app);
// `mbscope --screenshot FILE`: the window is rendered offscreen (decided before QApplication exists).
[[nodiscard]] bool guiWantsOffscreen(int argc, char *argv[]);
// `mbscope --session FILE`: QGuiApplication takes -session/--session for itself (X11 session
// management), so the option is taken out of argv before QApplication exists; runGui opens it.
void takeSessionArgument(int &argc, char *argv[]);
#endif

} // namespace mbscope::app
