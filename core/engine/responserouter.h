#pragma once

#include "inflightrequest.h"
#include "linkframing.h"

#include "exchange/responsematcher.h"

#include <QtCore/QList>

namespace mbscope {

// Which request a frame that came in answers, if any: a request in flight, one that timed out a
// moment ago (a late answer), one already answered (a duplicate), or none (unsolicited).
// It decides; the engine acts (judges, records, logs, counts). It remembers the requests that
// timed out (at most EngineOptions::lateWindow) and the last few answered ones.
//
// Timing truth: an answer cannot begin before its request was written, so a frame whose first
// byte came earlier belongs to an earlier request (late) or to none, whatever its keys say.
class ResponseRouter
{
public:
    struct Route {
        enum class Kind : quint8 {
            Answer,      // in flight at index, and its keys match
            Unexpected,  // in flight at index, its answer by timing, but a key differs (problem)
            Late,        // answers late, a request that timed out (taken out of the router)
            Duplicate,   // a second copy of an answer already recorded
            Unsolicited, // nobody's
        };
        Kind kind = Kind::Unsolicited;
        qsizetype index = -1;
    };
    // Two words, returned in registers: what goes with an Unexpected or a Late route is taken
    // from the router (problem(), takeLate()), so the answer of every frame costs nothing more.

    void reset(const LinkFraming &framing, int lateWindow);
    // Forgets what timed out and what was answered (a new target).
    void clear();

    // The keys of a frame in this framing (none for delimited framing).
    [[nodiscard]] FrameKeys keysOf(QByteArrayView frame) const;
    [[nodiscard]] Route route(const FrameKeys &keys, qint64 firstNs, const QList<InFlightRequest> &inFlight);
    // Unexpected: which key differs, and what the request expected.
    [[nodiscard]] const QString &problem() const { return m_problem; }
    // Late: the request it answers, taken out of the router.
    [[nodiscard]] InFlightRequest takeLate() { return std::move(m_late); }
    // An RTU answer the framer skipped (wrong CRC, cut short) may still name a request in flight
    // by its unit and function: its index, or -1.
    [[nodiscard]] qsizetype routeSkipped(QByteArrayView bytes, qint64 firstNs, const QList<InFlightRequest> &inFlight) const;

    void timedOut(const InFlightRequest &request, qint64 nowNs);
    void answered(const RequestItem &item);

private:
    [[nodiscard]] bool findLate(const FrameKeys &keys, qint64 firstNs);
    [[nodiscard]] bool isSecondCopyOfLatest(const FrameKeys &keys) const;
    [[nodiscard]] bool isDuplicate(const FrameKeys &keys) const;
    [[nodiscard]] Route unmatched(const FrameKeys &keys, qint64 firstNs);

    LinkFraming m_framing;
    int m_lateWindow = 0;
    QList<InFlightRequest> m_timedOut; // newest last, at most m_lateWindow
    QList<RequestItem> m_answered;     // recently answered requests, for second answers
    bool m_lastEndAnswered = false;    // the latest request to end was answered (not timed out)
    QString m_problem;                 // of the last Unexpected route
    InFlightRequest m_late;            // of the last Late route, until taken
};

} // namespace mbscope
