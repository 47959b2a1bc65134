#pragma once

#include "unitprobe.h"

#include "exchange/transaction.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>

namespace mbscope {

// A unit scan's verdict for one id, from the engine's verdict on the exchange (ResponseMatcher and
// ResponseVerdict decided it: this only names it for a scan) and every byte read meanwhile:
// - our own request read back (the exact bytes, whatever the engine made of them): Echo;
// - Ok: Answers; Exception 0A and 0B: the gateway's words (V1.1b3, 7), any other code: Exception;
// - Unexpected whose unit key differs: WrongUnit, with the id the answer carried;
// - CrcError, Malformed, any other Unexpected: Garbage, with the engine's problem;
// - Timeout with bytes read that made no answer: Garbage; with none: Silent;
// - LinkError: LinkError.
class UnitClassifier
{
public:
    [[nodiscard]] static UnitProbe classify(quint8 unit, const Transaction &transaction, Framing framing,
                                            const QByteArray &bytesRead);
};

} // namespace mbscope
