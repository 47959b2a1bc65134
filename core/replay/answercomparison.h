#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "replay/ignoredfields.h"

#include <QtCore/QStringList>

namespace mbscope {

// A replayed answer compared with the recorded one. Pure: two transactions (each with its own
// request, in its own framing) in, a verdict and its differences out. Answers are dissected
// against their requests and compared field by field by dissector key, so a recording made over
// RTU compares with a replay over Modbus TCP: the framing's own fields (MBAP header, CRC, LRC)
// are not the device's answer and are left out.
class AnswerComparison
{
public:
    enum class Verdict : quint8 {
        Match,          // same outcome, same field values
        ValuesDiffer,   // both answered alike (normal or the same exception), some fields differ
        OutcomeDiffers, // a normal answer against an exception, another exception code, a CRC error...
        MissingAnswer,  // recorded an answer, now none within the timeout
    };
    struct Result {
        Verdict verdict = Verdict::Match;
        // "modbus.register_value@0x007D: recorded 250, now 251", "recorded exception 0x02
        // (Illegal Data Address), now a normal answer", "no answer now (recorded a normal answer)"
        QStringList differences;
        // Differences in fields the user said would change (--ignore): reported, never a verdict.
        struct Ignored {
            QString selector;   // the --ignore selector that covers it
            QString difference; // as in differences
        };
        QList<Ignored> ignored;
        [[nodiscard]] bool matched() const { return verdict == Verdict::Match; }
    };

    [[nodiscard]] static Result compare(const Transaction &recorded, Framing recordedFraming, const Transaction &now,
                                        Framing nowFraming, const IgnoredFields &ignore = {});
    // "match", "values differ", "outcome differs", "missing answer"
    [[nodiscard]] static QString verdictName(Verdict verdict);
    // "a normal answer", "exception 0x02 (Illegal Data Address)", "no answer", "crc_error: ..."
    [[nodiscard]] static QString describeOutcome(const Transaction &transaction);
};

} // namespace mbscope
