#pragma once

#include <QtCore/QString>

namespace mbscope::app {

// A file a command will write when it is done (--histogram, --csv, --record, --junit...), checked
// before the first request: a run of minutes is never lost to a name that cannot be written.
class OutputPath
{
public:
    // Empty when path names a file that can be created or replaced in an existing, writable folder;
    // else what is wrong, with the option: "--csv 'out/x.csv': the folder .../out does not exist".
    // example is a correct use ("--csv poll.csv").
    [[nodiscard]] static QString problem(const QString &option, const QString &path, const QString &example);
    // problem() and, for a plot, the format its name says (.png, .svg or .pdf).
    [[nodiscard]] static QString plotProblem(const QString &option, const QString &path);
};

} // namespace mbscope::app
