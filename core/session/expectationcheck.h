#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "session/stepexpectation.h"

#include <QtCore/QStringList>

namespace mbscope {

// Checks one answer against a send step's expectation. Pure: the transaction as the engine
// recorded it in, a verdict and its reasons out ("modbus.register_value@0x0079 is 1049, expected
// 1050"). Fields are read by dissecting the answer with its request in the link's framing.
class ExpectationCheck
{
public:
    struct Outcome {
        QStringList failures; // what did not hold and what was seen instead
        QStringList checks;   // what held
        [[nodiscard]] bool passed() const { return failures.isEmpty(); }
    };
    // framing: the link's; delimited links carry no Modbus framing, so fields cannot be read there.
    // A request the dissector finds errors in adds requestProblem() to the failures of a step
    // that failed, and to the checks of one that passed (a bad CRC sent on purpose, expecting no
    // answer).
    [[nodiscard]] static Outcome check(const StepExpectation &expectation, const Transaction &transaction,
                                       Framing framing, bool delimited = false);
    // "the request itself is malformed, 1 error(s) (rtu.crc: ...)", as send says it; empty when
    // the request is well formed (or the link is delimited).
    [[nodiscard]] static QString requestProblem(const Transaction &transaction, Framing framing, bool delimited);
    // "no answer within the timeout", "an exception 0x02 (Illegal Data Address)", "a CRC error: ..."
    [[nodiscard]] static QString describeAnswer(const Transaction &transaction);

private:
    [[nodiscard]] static Outcome checkAnswer(const StepExpectation &expectation, const Transaction &transaction,
                                             Framing framing, bool delimited);
};

} // namespace mbscope
