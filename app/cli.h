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
// 3 is a run that went through but had nothing to show for it: monitor heard not one byte, or
// watch's --mqtt broker was never reached (every poll answered, nothing published). The man page's
// EXIT STATUS lists each command's statuses.
enum ExitStatus { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitLinkError = 2, ExitNothingHeard = 3, ExitNotPublished = 3 };

} // namespace mbscope::app
