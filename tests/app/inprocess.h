#pragma once

// Runs an mbscope subcommand inside the test's own process (issue 25, 5: a command can be tested
// without starting the binary): the dispatcher of the light executable (app/commands.cpp, built
// as mbscope_dispatch), with the test's QCoreApplication and event loop, its standard output and
// error caught in files for the time of the call. The test can serve the command from the same
// thread (a core Simulator on loopback): the command's event loop runs both.

#include <QtCore/QByteArray>
#include <QtCore/QStringList>

namespace mbscope::testcli {

struct InProcessRun {
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
};

// arguments without the program name: {"read", "--target", ...}.
[[nodiscard]] InProcessRun runInProcess(const QStringList &arguments);

} // namespace mbscope::testcli
