#pragma once

#include "common/printoptions.h"
#include "common/recordoptions.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"

#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

class QTextStream;

namespace mbscope::app {

// The front that the one-shot exchange commands (send, read, write) share: their options (with
// --record FILE and --force), --help,
// no positional arguments, and the target and requests read from the options.
struct ExchangeCommandSpec {
    const char *name = "";  // "send"
    QString description;    // --help's text above the options
    int requestGroups = 0;  // RequestOptions::Group flags
    QString jsonHelp;       // what --json prints
    QString positionalHint; // after "unexpected argument 'X': "
    bool readOutput = false; // read's -q/--terse (values one a line) and -1/--once (mbpoll's habit)
};

struct ExchangeCommandInput {
    TargetSettings target;
    RequestPlan plan;
    RecordSettings record;
    bool json = false;
    bool terse = false; // -q/--terse (read)
    PrintSettings print; // --print frames, --frame-log FILE
};

// Parses arguments into input. Returns the exit status when the command ends here (--help: 0;
// a usage problem, said on err: 2), or nothing when the exchange is to go on.
[[nodiscard]] std::optional<int> parseExchangeCommand(const ExchangeCommandSpec &spec, const QStringList &arguments,
                                                      QTextStream &out, QTextStream &err, ExchangeCommandInput &input);

// Runs input's requests against its target with what the options asked for around them (--print
// frames / --frame-log, --record) and returns the transactions; nothing when the frame log or the
// recording could not be opened (said on err: exit 2, before any byte is sent).
[[nodiscard]] std::optional<QList<Transaction>> runExchangeCommand(const ExchangeCommandSpec &spec,
                                                                  const QStringList &arguments,
                                                                  const ExchangeCommandInput &input, QTextStream &err);

} // namespace mbscope::app
