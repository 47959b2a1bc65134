#pragma once

#include <string>

namespace mbscope::app {

// mbscope is two executables (docs/architecture.md, "app/"): `mbscope`, light, links the core and
// the command line only (QtCore, QtNetwork, QtSerialPort), and runs the commands that talk to a
// device or read a file; mbscope-full, installed beside it, links everything else (the window,
// QCustomPlot, the simulator with its scripts and Qt SerialBus, the watch service's HTTP server
// and MQTT) and runs every command. `mbscope` decides from its arguments alone, before Qt starts,
// and execs mbscope-full for what it cannot run: the same process (pid, standard streams,
// signals) goes on as mbscope-full with the same arguments.
class Launcher
{
public:
    // No subcommand (the window and its options), --help-all, a subcommand that runs only in
    // mbscope-full (runsHere), a plot (--histogram, --timeseries: HistogramPlot::isRequested), or
    // a poll or sweep with --profile (ProfileLimits::isRequested).
    // --help, --version, unknown words and every light subcommand's --help stay here.
    [[nodiscard]] static bool needsFull(int argc, char *argv[]);
    // Where mbscope-full is: beside this executable (its real path, symbolic links resolved).
    [[nodiscard]] static std::string fullPath();
    // Replaces this process by mbscope-full with the same arguments. Returns only when it cannot
    // (the file is missing or not executable): the message is printed, the exit status is 2.
    [[nodiscard]] static int execFull(char *argv[]);
};

} // namespace mbscope::app
