#pragma once

// The shell examples of a Markdown page, as tst_docexamples runs them: fenced blocks tagged sh,
// shell, bash or console. An sh block is a script as it stands; in a console block the lines
// after "$ " are the commands (a line ending in a backslash continues on the next) and the
// others are their output, which is not run.
//
// HTML comments on the lines just before a fence steer the test, unseen on the rendered page:
//   <!-- docs-test: skip (why) -->          not run, for the reason given (hardware, a display...)
//   <!-- docs-test: exit N -->              the last command exits with N (the rest with 0)
//   <!-- docs-test: setup COMMAND -->       a command run before the block (what the text around
//                                          it says is already running); several are run in order
//   <!-- docs-test: sub OLD => NEW -->      OLD replaced by NEW in the block before it runs (a long
//                                          poll made shorter)
//   <!-- docs-test: stop after N s -->      the block runs until stopped (a service): still running
//                                          after N seconds is a pass, and it is stopped then
//   <!-- docs-test: timeout N s -->         more than the default 60 s allowed
// A directive the test does not know is reported as a failure, so a typo is not a silent skip.

#include <QtCore/QList>
#include <QtCore/QPair>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testdocs {

struct ShellBlock {
    int line = 0;          // the opening fence's, 1-based
    QString language;      // sh, console, ...
    QString script;        // the commands, one per line (console: without "$ ")
    QString skip;          // the reason, when skipped
    int exitStatus = 0;    // of the last command
    QStringList setup;     // run first
    QList<QPair<QString, QString>> substitutions;
    int stopAfterSeconds = 0; // 0: runs to its end
    int timeoutSeconds = 60;
    QStringList problems;  // directives not understood
};

// Every runnable block of the page; untagged fences whose first line is a command ("$ " or
// "mbscope ") come back too, with a problem saying to tag them, so none escapes the test.
[[nodiscard]] QList<ShellBlock> shellBlocks(const QString &markdown);

// The examples of a subcommand's --help, as blocks to run the same way: a line that starts with
// "Example" and ends with a colon opens a block; the lines after it that start with two spaces and
// "mbscope " are its commands, run in order. A simulator named on the opening line in parentheses,
// "(with mbscope simulate --profile P --listen URL running)", is the block's setup: started first
// (quiet, in the background), the commands run once it listens; "(not run by the tests: why)"
// there skips the block, for the reason given. A help with no example of
// `mbscope command`, or with a command on the opening line itself, comes back as a block with a
// problem saying so.
[[nodiscard]] QList<ShellBlock> helpBlocks(const QString &help, const QString &command);

} // namespace mbscope::testdocs
