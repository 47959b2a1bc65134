#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// What one unit id did when asked a harmless read during a unit scan.
enum class UnitProbeKind : quint8 {
    Answers,                // a matching, well-formed answer
    Exception,              // a matching exception answer other than the gateway ones (exceptionCode)
    GatewayPathUnavailable, // exception 0A: the gateway has no path to that unit (V1.1b3, 7)
    GatewayTargetFailed,    // exception 0B: the gateway's target did not respond (V1.1b3, 7)
    Silent,                 // nothing within the timeout
    WrongUnit,              // an answer carrying another unit's id (answeredUnit)
    Garbage,                // bytes that were no valid answer: wrong CRC, malformed, another function
    Echo,                   // our own request came back (a 2-wire adapter echoing, a loop)
    LinkError,              // the link failed (refused, closed) before an answer
};

// "answers", "exception", "gateway_path_unavailable", "gateway_target_failed", "silent",
// "wrong_unit", "garbage", "echo", "link_error": the words of the table and of --json.
[[nodiscard]] const char *unitProbeKindName(UnitProbeKind kind);

// The result for one unit id.
struct UnitProbe {
    quint8 unit = 0;
    UnitProbeKind kind = UnitProbeKind::Silent;
    quint8 exceptionCode = 0; // Exception, GatewayPathUnavailable, GatewayTargetFailed
    quint8 answeredUnit = 0;  // WrongUnit: the id the answer carried
    qint64 latencyNs = -1;    // request sent to answer done; -1 without an answer
    QString problem;          // the engine's words for what was wrong (empty for Answers)
    QByteArray request;       // the bytes sent
    QByteArray response;      // the bytes that came back (for Garbage and Echo: every byte read)

    // A device is there: it answered, with data or with an exception of its own.
    [[nodiscard]] bool isPresent() const
    {
        return kind == UnitProbeKind::Answers || kind == UnitProbeKind::Exception;
    }
    // One line for people: "answers", "exception 02 (illegal data address)", "answered as unit 4".
    [[nodiscard]] QString summary() const;

    // So many unit addresses (1-247) asked, every one answering: one device that ignores the unit
    // id, not that many devices (fewer could be real units: a gateway with three).
    static constexpr int kIgnoresUnitId = 16;
    [[nodiscard]] static bool oneDeviceIgnoringUnitId(const QList<UnitProbe> &probes)
    {
        int present = 0;
        for (const UnitProbe &p : probes) {
            if (p.unit < 1 || p.unit > 247)
                continue;
            if (!p.isPresent())
                return false;
            ++present;
        }
        return present >= kIgnoresUnitId;
    }
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::UnitProbe)
