#pragma once

#include "common/integeroption.h"
#include "common/targetpieces.h"

#include "transport/linkurl.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

class QCommandLineParser;
class QTextStream;

namespace mbscope::app {

// Where a subcommand talks to and how long it waits, read from its options.
struct TargetSettings {
    LinkUrl url;
    int timeoutMs = 1000; // the response timeout of every request
    int retries = 0;      // further attempts after a timeout or an unusable answer
};

// The options every subcommand that talks to a device shares:
//   --target URL        tcp://host:502, rtu-tcp://host:4001, rtu:///dev/ttyUSB0?baud=9600 ...
//                       or, as mbpoll takes it, a host or a serial device with TargetPieces'
//                       options (-m, -p, -b, -P, -d, -s); the target may also be the one
//                       positional argument ("mbscope read -a 1 -r 0 -c 10 192.168.1.10")
//   --timeout DURATION  response timeout (default: the URL's timeout=, else 1000 ms)
//   -o, --timeout-s S   the same in seconds when bare, as mbpoll's -o
//   --retries N         further attempts after a timeout or an unusable answer (default 0)
// Errors name the option and say what was expected.
class TargetOptions
{
public:
    // withRetries false: no --retries (a command that judges every answer as it comes, conform).
    explicit TargetOptions(bool withRetries = true);

    void addTo(QCommandLineParser &parser) const;
    // Reads the options and the positional target; on error writes "mbscope COMMAND: ..." to err
    // and returns false. positionalHint follows "unexpected argument 'X': " when there are more
    // positional arguments than the one target.
    [[nodiscard]] bool read(const QCommandLineParser &parser, const QString &command, TargetSettings &out,
                            QTextStream &err, const QString &positionalHint = {}) const;

private:
    TargetPieces m_pieces;
    QCommandLineOption m_target;
    QCommandLineOption m_timeout;
    QCommandLineOption m_timeoutSeconds;
    QCommandLineOption m_retries;
    bool m_withRetries = true;
};

} // namespace mbscope::app
