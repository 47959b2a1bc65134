#pragma once

#include "conformancecheck.h"
#include "conformancelink.h"

#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// The verdicts the checks share, each from the raw bytes of one exchange: an exception with the
// right code, a well-formed normal answer, silence, silence or an exception. A failure is one
// sentence: what was sent, what came back, what the check's clause requires.
class ConformanceJudge
{
public:
    // Passes when the answer is the exception response (function + 0x80) with one of codes.
    static bool exception(CheckResult &result, const ConformanceExchange &e, const QList<quint8> &codes,
                          const QString &requirement);
    // Passes when the answer is a well-formed normal answer to the request (the dissector finds no error).
    static bool normal(CheckResult &result, const ConformanceExchange &e, const QString &requirement);
    // Passes when nothing came back within the wait (extra: bytes read after it, listened for).
    // closing: a connection the device closes without an answer is silence too (a request it
    // cannot frame, after which a server may drop the connection).
    static bool silence(CheckResult &result, const ConformanceExchange &e, const QString &requirement,
                        const QByteArray &extra = {}, bool closing = false);
    // Passes on silence (a connection closed without an answer too) or on a well-formed exception response.
    static bool silenceOrException(CheckResult &result, const ConformanceExchange &e, const QString &requirement);

    // "01 03 00 00 00 01 84 0A"
    [[nodiscard]] static QString hex(const QByteArray &bytes);
    // What came back, in words: "no answer within 1000 ms", "01 83 02 C0 F1 (exception 02 Illegal
    // Data Address)", "01 03 02 00 2A 39 95 (a normal answer)", "... (malformed: ...)".
    [[nodiscard]] static QString seen(const ConformanceExchange &e);
    // "sent X; got Y; V1.1b3 6.3 requires Z"
    [[nodiscard]] static QString failure(const CheckResult &result, const ConformanceExchange &e, const QString &requirement);
    // The PDU of an answer in framing (function code first), or empty.
    [[nodiscard]] static QByteArray pdu(const QByteArray &adu, Framing framing);
    // "exception 03 (Illegal Data Value)"
    [[nodiscard]] static QString exceptionText(quint8 code);
    static void record(CheckResult &result, const ConformanceExchange &e);
};

} // namespace mbscope
