#pragma once

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope::bench {

// bench_tap's serial section: `mbscope tap --listen tcp://127.0.0.1:0 --target rtu://A?baud=B` in
// front of `mbscope simulate --profile conformance --listen rtu://B?baud=B --quiet`, the two ptys
// joined either by socat (bytes pass at once: a pty has no baud rate) or by a PacedLine (each
// byte takes its character time, one direction at a time). `masters` libmodbus masters send
// through the tap at once, so that its queue for the line is never empty; their transactions/s
// are printed beside the line's limit: one request (8 characters) and its answer (25) on the line,
// each followed by t3.5 of silence.
struct SerialBenchOptions {
    QList<int> bauds{115200, 19200};
    int masters = 4;
    int requestsPerMaster = 200;
    QString mbscope;
    bool pin = true;
    int serverCpu = 0;
    int clientCpu = 1;
};

// Prints the section; 0 when every answer was right, 1 when a master saw an error, 2 when
// something could not start.
int runSerialSection(const SerialBenchOptions &options);

} // namespace mbscope::bench
