#pragma once

#include <QtCore/QString>

// What every subcommand shares: exit statuses and the --help text's usage line.
// The dispatcher (which subcommand runs) is commands.h.

namespace mbscope::app {

// A subcommand's --help text with its real usage line ("Usage: mbscope analyze [options] capture")
// instead of the executable's path that QCommandLineParser puts there.
[[nodiscard]] QString subcommandHelp(const QString &helpText, const char *name);

// Exit statuses shared by every subcommand.
// A link error (nothing reached the device: refused, no such host or port) ends a command as a
// usage error does: the command could not do what it was asked.
enum ExitStatus { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitLinkError = 2 };

} // namespace mbscope::app
