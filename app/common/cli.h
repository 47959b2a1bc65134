#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

// What every subcommand shares: exit statuses and the --help text's usage line.
// The dispatcher (which subcommand runs) is commands.h.

namespace mbscope::app {

// A subcommand's --help text with its real usage line ("Usage: mbscope analyze [options] capture")
// instead of the executable's path that QCommandLineParser puts there.
[[nodiscard]] QString subcommandHelp(const QString &helpText, const char *name);

// While one exists, subcommandHelp hands its text to it and returns an empty string, so that a
// subcommand run with --help prints nothing: `mbscope completion` reads every subcommand's help
// (what --help-all prints) this way, from the parsers themselves.
class HelpCapture
{
public:
    HelpCapture();
    ~HelpCapture();
    HelpCapture(const HelpCapture &) = delete;
    HelpCapture &operator=(const HelpCapture &) = delete;
    // What the subcommands' --help gave since the last take().
    [[nodiscard]] QString take();

private:
    friend QString subcommandHelp(const QString &helpText, const char *name);
    HelpCapture *m_previous = nullptr;
    QString m_text;
};

// A subcommand as `mbscope --help` lists it, with what its own --help prints.
struct SubcommandHelp {
    QString name;
    QString summary; // the line `mbscope --help` shows
    QString help;    // what `mbscope NAME --help` prints
};

// What the dispatcher knows that a command about the command line needs (completion): every
// subcommand with its --help, read only when asked, and the options mbscope takes without one.
struct CommandLineIndex {
    QList<SubcommandHelp> (*subcommands)() = nullptr;
    QStringList topLevelOptions;
};

// Exit statuses shared by every subcommand.
// A link error (nothing reached the device: refused, no such host or port) ends a command as a
// usage error does: the command could not do what it was asked.
// 3 is a run that went through but had nothing to show for it: monitor heard not one byte, or
// watch's --mqtt broker was never reached (every poll answered, nothing published). The man page's
// EXIT STATUS lists each command's statuses.
enum ExitStatus { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitLinkError = 2, ExitNothingHeard = 3, ExitNotPublished = 3 };

} // namespace mbscope::app
