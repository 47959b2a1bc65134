#include "serialtimingchecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"
#include "readchecks.h"

#include "protocol/rtuframer.h"
#include "transport/seriallink.h"

#include <algorithm>
#include <limits>

namespace mbscope {

namespace {

constexpr int kSamples = 5;

QString ms(qint64 ns)
{
    return QStringLiteral("%1 ms").arg(double(ns) / 1e6, 0, 'f', 2);
}

QByteArray harmlessRead(const ConformanceContext &ctx)
{
    for (quint8 f : {quint8(0x03), quint8(0x04), quint8(0x01), quint8(0x02)}) {
        const int at = ctx.readable(SimTable(ReadChecks::tableOf(f)));
        if (at >= 0 && ctx.support(f) == SurveyedSupport::Supported)
            return ReadChecks::readPdu(f, at, 1);
    }
    return ReadChecks::readPdu(0x03, 0, 1);
}

// The line's numbers for the link's settings.
struct Line {
    int baud = 0;
    qint64 characterNs = 0;
    qint64 t15Ns = 0;
    qint64 t35Ns = 0;
    [[nodiscard]] QString limits() const
    {
        return QStringLiteral("t1.5 = %1, t3.5 = %2 at %3 baud").arg(ms(t15Ns), ms(t35Ns)).arg(baud);
    }
};

Line lineOf(const ConformanceContext &ctx)
{
    const SerialSettings &s = const_cast<ConformanceContext &>(ctx).link().url().serial;
    return {s.baud, SerialLink::lineCharacterNs(s), RtuFramer::t15Ns(s.baud), RtuFramer::t35Ns(s.baud)};
}

// kSamples reads, each answer's engine record kept.
struct Samples {
    QList<ConformanceExchange> answered; // a whole normal or exception answer
    QList<ConformanceExchange> onLine;   // of those, the ones whose times follow the line (not outran)
    ConformanceExchange last;
};

Samples ask(ConformanceContext &ctx)
{
    Samples out;
    const QByteArray pdu = harmlessRead(ctx);
    for (int i = 0; i < kSamples; ++i) {
        const ConformanceExchange e = ctx.ask(pdu);
        out.last = e;
        if (e.transaction.response.isEmpty() || e.transaction.firstByteNs <= 0 || e.transaction.doneNs <= 0)
            continue;
        out.answered.append(e);
        if (!e.transaction.outranLine)
            out.onLine.append(e);
    }
    return out;
}

// Why the samples say nothing of the line, or empty.
QString unmeasurable(const Samples &s, const Line &line)
{
    if (s.answered.isEmpty())
        return QStringLiteral("not judged: none of %1 reads was answered").arg(kSamples);
    if (line.baud <= 0 || line.characterNs <= 0)
        return QStringLiteral("not judged: not measurable on this link: the link has no baud rate to time the line by");
    if (s.onLine.isEmpty())
        return QStringLiteral("not judged: not measurable on this link: the answers came sooner than the line at %1 baud can "
                              "carry request and answer (a pseudo terminal, or an adapter that buffers), so the host's times "
                              "are not the line's")
            .arg(line.baud);
    return {};
}

ConformanceCheck check(const char *id, const char *title, std::function<void(ConformanceContext &, CheckResult &)> run)
{
    ConformanceCheck c;
    c.id = QLatin1String(id);
    c.title = QLatin1String(title);
    c.clause = QStringLiteral("Serial Line V1.02, 2.5.1.1");
    c.level = CheckLevel::Mandatory;
    c.needs.serialPort = true;
    c.run = std::move(run);
    return c;
}

} // namespace

QList<ConformanceCheck> SerialTimingChecks::checks()
{
    QList<ConformanceCheck> out;

    // The answer's first character began at the latest one character before the read that
    // brought it, and n characters before the read that brought its last byte; the request's
    // computed end can only be early. So the silence measured is at least the real one: shorter
    // than t3.5, the device broke the rule.
    out.append(check("serial.t35-before-answer", "the answer starts no sooner than t3.5 after the request",
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const Line line = lineOf(ctx);
                         const Samples s = ask(ctx);
                         ConformanceJudge::record(res, s.last);
                         if (const QString why = unmeasurable(s, line); !why.isEmpty()) {
                             res.skip(why);
                             return;
                         }
                         qint64 shortest = std::numeric_limits<qint64>::max();
                         const ConformanceExchange *worst = nullptr;
                         for (const ConformanceExchange &e : s.onLine) {
                             const Transaction &t = e.transaction;
                             const qint64 start = std::min(t.firstByteNs - line.characterNs,
                                                           t.doneNs - qint64(t.response.size()) * line.characterNs);
                             const qint64 silence = start - t.sentNs;
                             if (silence < shortest) {
                                 shortest = silence;
                                 worst = &e;
                             }
                         }
                         ConformanceJudge::record(res, *worst);
                         res.measured = QStringLiteral("silence before the answer: at most %1 in the shortest of %2 answers (%3)")
                                            .arg(ms(shortest))
                                            .arg(s.onLine.size())
                                            .arg(line.limits());
                         if (shortest < line.t35Ns) {
                             res.fail(QStringLiteral("sent %1; its answer %2 began at most %3 after the request's end on the line "
                                                     "(the host's reads can only make it look later); %4 requires a silence of at "
                                                     "least 3.5 characters (%5 at %6 baud) between frames")
                                          .arg(ConformanceJudge::hex(worst->request), ConformanceJudge::hex(worst->transaction.response),
                                               ms(shortest), res.clause, ms(line.t35Ns))
                                          .arg(line.baud));
                             return;
                         }
                         res.pass(QStringLiteral("every answer began %1 or more after the request's end as the host timed the "
                                                 "line (t3.5 = %2 at %3 baud)")
                                      .arg(ms(shortest), ms(line.t35Ns))
                                      .arg(line.baud));
                     }));

    // Inside an answer: from its first read to its last, the characters after the first took at
    // most n - 1 character times, so what is left is silence, spread over at most n - 1 gaps.
    // More than (n - 1) x t1.5 of it means one gap was longer than t1.5. The link records when
    // the first and the last read came, not each byte: an answer read at once shows no gaps.
    out.append(check("serial.t15-within-answer", "no silence inside an answer exceeds t1.5",
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const Line line = lineOf(ctx);
                         const Samples s = ask(ctx);
                         ConformanceJudge::record(res, s.last);
                         if (const QString why = unmeasurable(s, line); !why.isEmpty()) {
                             res.skip(why);
                             return;
                         }
                         int oneRead = 0;
                         qint64 most = -1;
                         qint64 mostSpan = 0;
                         const ConformanceExchange *worst = nullptr;
                         for (const ConformanceExchange &e : s.onLine) {
                             const Transaction &t = e.transaction;
                             if (t.doneNs <= t.firstByteNs) {
                                 ++oneRead;
                                 continue;
                             }
                             const qint64 gaps = qint64(t.response.size()) - 1;
                             const qint64 silence = (t.doneNs - t.firstByteNs) - gaps * line.characterNs;
                             // The longest gap is at least the silence shared out evenly.
                             const qint64 longestAtLeast = gaps > 0 ? silence / gaps : 0;
                             if (longestAtLeast > most) {
                                 most = longestAtLeast;
                                 mostSpan = t.doneNs - t.firstByteNs;
                                 worst = &e;
                             }
                         }
                         if (!worst) {
                             res.skip(QStringLiteral("not judged: not measurable on this link: each of the %1 answers came in "
                                                     "one read (an adapter's buffer or the line relay gathered it), so the gaps "
                                                     "between its characters are not seen")
                                          .arg(oneRead));
                             return;
                         }
                         ConformanceJudge::record(res, *worst);
                         res.measured = QStringLiteral("answer of %1 bytes read over %2: its longest silence at least %3 (%4)")
                                            .arg(worst->transaction.response.size())
                                            .arg(ms(mostSpan), ms(std::max<qint64>(0, most)), line.limits());
                         if (most > line.t15Ns) {
                             res.fail(QStringLiteral("sent %1; the %2 bytes of its answer %3 took %4 from the first read to the "
                                                     "last, so at least one silence between its characters lasted %5 or more; %6 "
                                                     "requires the characters of a frame to follow with no silence over 1.5 "
                                                     "characters (%7 at %8 baud)")
                                          .arg(ConformanceJudge::hex(worst->request))
                                          .arg(worst->transaction.response.size())
                                          .arg(ConformanceJudge::hex(worst->transaction.response), ms(mostSpan), ms(most), res.clause,
                                               ms(line.t15Ns))
                                          .arg(line.baud));
                             return;
                         }
                         // The reads do not say how many bytes came in the first: the silence could
                         // all be one gap. Only when all of it fits in t1.5 is no gap too long.
                         const qint64 upTo = mostSpan - line.characterNs;
                         if (upTo <= line.t15Ns) {
                             res.pass(QStringLiteral("the answers' reads leave no room for a silence over %1").arg(ms(line.t15Ns)));
                             return;
                         }
                         res.skip(QStringLiteral("not judged: the answer's reads span %1, room for one silence of up to %2 "
                                                 "(t1.5 = %3); the link records the first and the last read of an answer, not "
                                                 "each byte's arrival")
                                      .arg(ms(mostSpan), ms(upTo), ms(line.t15Ns)));
                     }));
    return out;
}

} // namespace mbscope
