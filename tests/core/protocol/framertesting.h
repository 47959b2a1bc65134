#pragma once

// Shared by the framer tests: feed a stream in several ways and describe what came out as lines
// that read like the expectations ("frame @8 0103...15DD", "skip @0 2 crc"), which frame() and
// skip() write.

#include "protocol/streamframer.h"

#include <QtCore/QRandomGenerator>
#include <QtCore/QStringList>
#include <QtTest/QtTest>

#include <algorithm>
#include <functional>
#include <memory>

namespace framertesting {

using Factory = std::function<std::unique_ptr<mbscope::StreamFramer>()>;

inline const char *reasonToken(mbscope::SkipReason reason)
{
    using mbscope::SkipReason;
    switch (reason) {
    case SkipReason::NoFrameStart: return "noframe";
    case SkipReason::InvalidHeader: return "header";
    case SkipReason::ChecksumMismatch: return "crc";
    case SkipReason::ImpossibleFunction: return "function";
    case SkipReason::NoLengthRule: return "norule";
    case SkipReason::Abandoned: return "abandoned";
    case SkipReason::TooLong: return "toolong";
    case SkipReason::Incomplete: return "incomplete";
    case SkipReason::AfterGap: return "aftergap";
    }
    return "?";
}

inline const char *statusToken(mbscope::FrameStatus status)
{
    using mbscope::FrameStatus;
    switch (status) {
    case FrameStatus::Valid: return "";
    case FrameStatus::Unverified: return " unverified";
    case FrameStatus::Truncated: return " truncated";
    case FrameStatus::Malformed: return " malformed";
    }
    return " ?";
}

// "frame @offset HEX[ status]": status is "" (valid) or " unverified", " truncated", " malformed".
inline QString frame(qint64 offset, const QByteArray &bytes, const char *status = "")
{
    return QStringLiteral("frame @%1 %2%3").arg(offset).arg(QString::fromLatin1(bytes.toHex().toUpper()),
                                                             QLatin1String(status));
}

// "skip @offset count reason", reason as reasonToken() writes it.
inline QString skip(qint64 offset, qint64 count, const char *reason)
{
    return QStringLiteral("skip @%1 %2 %3").arg(offset).arg(count).arg(QLatin1String(reason));
}

struct Outcome {
    QList<mbscope::StreamFrame> frames;
    QList<mbscope::SkippedBytes> skipped;
    qsizetype pending = 0;

    void take(mbscope::StreamFramer &framer)
    {
        frames.append(framer.takeFrames());
        skipped.append(framer.takeSkipped());
        pending = framer.pendingSize() + framer.openSkippedRunSize();
    }

    // Frames and skipped runs in stream order, one line each.
    [[nodiscard]] QStringList describe() const
    {
        QList<std::pair<qint64, QString>> lines;
        for (const auto &f : frames)
            lines.append({f.offset, frame(f.offset, f.bytes, statusToken(f.status))});
        for (const auto &run : skipped)
            lines.append({run.offset, skip(run.offset, run.count(), reasonToken(run.reason))});
        std::stable_sort(lines.begin(), lines.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
        QStringList out;
        for (const auto &line : lines)
            out.append(line.second);
        return out;
    }

    // Every byte fed is in exactly one frame or skipped run, or still pending, in order.
    [[nodiscard]] bool accountsFor(qint64 total) const
    {
        QList<std::pair<qint64, qint64>> spans;
        for (const auto &frame : frames)
            spans.append({frame.offset, frame.bytes.size()});
        for (const auto &run : skipped)
            spans.append({run.offset, run.count()});
        std::sort(spans.begin(), spans.end());
        qint64 next = 0;
        for (const auto &span : spans) {
            if (span.first != next || span.second <= 0)
                return false;
            next += span.second;
        }
        return next + pending == total;
    }
};

// Feeds the stream in chunks that end at the given cut positions; silence at the end if asked.
inline Outcome feedCuts(const Factory &make, const QByteArray &stream, const QList<qsizetype> &cuts, bool silence)
{
    auto framer = make();
    Outcome outcome;
    qsizetype from = 0;
    for (qsizetype cut : cuts) {
        framer->feed(QByteArrayView(stream).sliced(from, cut - from));
        outcome.take(*framer);
        from = cut;
    }
    framer->feed(QByteArrayView(stream).sliced(from));
    if (silence)
        framer->flushOnSilence();
    outcome.take(*framer);
    return outcome;
}

// Whole, one byte at a time, in chunks of 2, 3 and 7, and cut in two at every position: all must
// give the expected lines, and account for every byte.
inline void checkAllChunkings(const Factory &make, const QByteArray &stream, const QStringList &expected, bool silence)
{
    auto check = [&](const QList<qsizetype> &cuts, const char *how) {
        const Outcome outcome = feedCuts(make, stream, cuts, silence);
        const QStringList got = outcome.describe();
        if (got != expected) {
            qWarning() << "fed" << how << "cuts" << cuts;
            QCOMPARE(got, expected);
        }
        QVERIFY2(outcome.accountsFor(stream.size()), how);
    };
    check({}, "whole");
    for (qsizetype step : {1, 2, 3, 7}) {
        QList<qsizetype> cuts;
        for (qsizetype at = step; at < stream.size(); at += step)
            cuts.append(at);
        if (QTest::currentTestFailed())
            return;
        check(cuts, "in steps");
    }
    for (qsizetype at = 1; at < stream.size() && !QTest::currentTestFailed(); ++at)
        check({at}, "cut in two");
}

// The stream test of a framer: columns stream, expected (lines) and silence, after any columns of
// the framer's own settings; each row checked by checkAllChunkings.
inline void streamColumns()
{
    QTest::addColumn<QByteArray>("stream");
    QTest::addColumn<QStringList>("expected");
    QTest::addColumn<bool>("silence");
}

inline void checkStreamRow(const Factory &make)
{
    QFETCH(QByteArray, stream);
    QFETCH(QStringList, expected);
    QFETCH(bool, silence);
    checkAllChunkings(make, stream, expected, silence);
}

// Feeds the stream whole, then in random chunks of 1 to maxChunk - 1 bytes (a silence at the end
// of both when asked): the chunked run must give the same lines, account for every byte and never
// hold more than maxPending bytes.
inline void checkRandomChunks(const Factory &make, const QByteArray &stream, QRandomGenerator &random, int maxChunk,
                              qsizetype maxPending, bool silence)
{
    auto whole = make();
    whole->feed(stream);
    if (silence)
        whole->flushOnSilence();
    Outcome reference;
    reference.take(*whole);
    QVERIFY(reference.accountsFor(stream.size()));

    auto chunked = make();
    Outcome outcome;
    for (qsizetype at = 0; at < stream.size();) {
        const qsizetype length = qMin<qsizetype>(random.bounded(1, maxChunk), stream.size() - at);
        chunked->feed(QByteArrayView(stream).sliced(at, length));
        QVERIFY(chunked->pendingSize() < maxPending);
        outcome.take(*chunked);
        at += length;
    }
    if (silence)
        chunked->flushOnSilence();
    outcome.take(*chunked);
    QCOMPARE(outcome.describe(), reference.describe());
    QVERIFY(outcome.accountsFor(stream.size()));
}

} // namespace framertesting
