#pragma once

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

namespace mbscope::app {

// A file a command will write (--record, --csv, --jsonl, --pcap, --histogram, --timeseries,
// --junit, --watches, --profile-out...), checked before the first request: a run of minutes is
// never lost to a name that cannot be written. One policy for every output of every command:
//  - a file that exists is refused unless --force is given (nothing is overwritten by surprise);
//  - a file that does not exist is created (and removed again) now, so a folder that is missing
//    or read-only, or a file system that takes no files (/proc, a read-only mount), is said
//    before any traffic, not after the work is done;
//  - a file that exists, with --force, is opened for writing (not truncated) to prove it can be.
// "-" (standard output, where a command allows it) is never checked.
class OutputPath
{
public:
    // Empty when path can be written under the policy; else what is wrong, with the option:
    // "--csv: cannot write .../out/x.csv: the folder does not exist". example is a correct use
    // ("--csv poll.csv"); what names the kind of file in the refusal of an existing one ("a
    // journal" is never overwritten...).
    [[nodiscard]] static QString problem(const QString &option, const QString &path, const QString &example, bool force,
                                         const QString &what = QStringLiteral("an output file"));
    // problem() and, for a plot, the format its name says (.png, .svg or .pdf).
    [[nodiscard]] static QString plotProblem(const QString &option, const QString &path, bool force);
    // --force, for commands whose outputs are not --record's (export, analyze, scan).
    [[nodiscard]] static QCommandLineOption forceOption();
};

} // namespace mbscope::app
