#pragma once

#include <QtCore/QStringList>

#ifdef MBSCOPE_HAVE_UI
class QApplication;
#endif

namespace mbscope::app {

[[nodiscard]] bool isSubcommand(const char *name);
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

// A subcommand's --help text with its real usage line ("Usage: mbscope poll [options]") instead of
// the executable's path that QCommandLineParser puts there.
[[nodiscard]] QString subcommandHelp(const QString &helpText, const char *name);

// Exit statuses shared by every subcommand.
// A link error (nothing reached the device: refused, no such host or port) ends a command as a
// usage error does: the command could not do what it was asked.
enum ExitStatus { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitLinkError = 2 };

} // namespace mbscope::app
