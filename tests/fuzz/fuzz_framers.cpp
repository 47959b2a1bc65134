// libFuzzer target over the stream framers (RTU, MBAP, ASCII). Any byte stream, fed in any
// chunking, must be cut into frames and skipped runs that together are exactly the stream, in
// order, with nothing left pending after a silence; and, without silences in between, the
// chunking must not change the result (streamframer.h promises both). Every frame is then
// dissected in its framing.
//
// Input layout:
//   byte 0   framer: 0 RTU (direction auto), 1 RTU requests, 2 RTU responses, 3 MBAP, 4 ASCII
//            (wraps around)
//   byte 1   bits 0-1: chunking: 1 byte, 64 bytes, pseudo-random 1-300 bytes, all at once
//            bits 2-6: seed of the pseudo-random chunk sizes
//            bit 7:    a silence after every chunk (then the chunking may change the frames, so
//                      only the stream-coverage rules are checked)
//   the rest is the stream
#include "protocol/asciiframer.h"
#include "protocol/dissector.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

struct Output {
    QList<StreamFrame> frames;
    QList<SkippedBytes> skipped;
};

std::unique_ptr<StreamFramer> makeFramer(int kind)
{
    switch (kind) {
    case 0: return std::make_unique<RtuFramer>(Direction::Auto);
    case 1: return std::make_unique<RtuFramer>(Direction::Request);
    case 2: return std::make_unique<RtuFramer>(Direction::Response);
    case 3: return std::make_unique<MbapFramer>();
    default: return std::make_unique<AsciiFramer>();
    }
}

void collect(StreamFramer &framer, Output &out)
{
    out.frames += framer.takeFrames();
    out.skipped += framer.takeSkipped();
}

Output run(int kind, const QByteArray &stream, int chunking, std::uint32_t seed, bool silences)
{
    std::unique_ptr<StreamFramer> framer = makeFramer(kind);
    Output out;
    qsizetype at = 0;
    qint64 now = 0;
    while (at < stream.size()) {
        qsizetype chunk = stream.size();
        switch (chunking) {
        case 0: chunk = 1; break;
        case 1: chunk = 64; break;
        case 2:
            seed = seed * 1103515245u + 12345u;
            chunk = 1 + qsizetype((seed >> 16) % 300);
            break;
        default: break;
        }
        chunk = qMin(chunk, stream.size() - at);
        now += 1000;
        framer->feed(QByteArrayView(stream).sliced(at, chunk), now);
        at += chunk;
        if (silences)
            framer->flushOnSilence();
        collect(*framer, out);
        // Memory stays bounded: what is pending never exceeds the largest frame plus one chunk.
        check(framer->pendingSize() <= 600 + chunk);
    }
    framer->flushOnSilence();
    collect(*framer, out);
    check(framer->pendingSize() == 0);
    check(framer->openSkippedRunSize() == 0);
    check(framer->streamSize() == stream.size());
    return out;
}

// Frames and skipped runs, merged by offset, are the stream itself: contiguous, in order, equal bytes.
void checkCoverage(const QByteArray &stream, const Output &out)
{
    qint64 at = 0;
    qsizetype f = 0;
    qsizetype s = 0;
    while (f < out.frames.size() || s < out.skipped.size()) {
        const bool takeFrame = s >= out.skipped.size()
                               || (f < out.frames.size() && out.frames[f].offset <= out.skipped[s].offset);
        const QByteArray &bytes = takeFrame ? out.frames[f].bytes : out.skipped[s].bytes;
        const qint64 offset = takeFrame ? out.frames[f].offset : out.skipped[s].offset;
        check(!bytes.isEmpty());
        check(offset == at);
        check(stream.mid(offset, bytes.size()) == bytes);
        at += bytes.size();
        if (takeFrame) {
            check(out.frames[f].status == FrameStatus::Valid || !out.frames[f].problem.isEmpty());
            ++f;
        } else {
            check(out.skipped[s].bytes.size() <= 256);
            ++s;
        }
    }
    check(at == stream.size());
}

bool same(const Output &a, const Output &b)
{
    if (a.frames.size() != b.frames.size() || a.skipped.size() != b.skipped.size())
        return false;
    for (qsizetype i = 0; i < a.frames.size(); ++i) {
        if (a.frames[i].bytes != b.frames[i].bytes || a.frames[i].offset != b.frames[i].offset
            || a.frames[i].status != b.frames[i].status)
            return false;
    }
    for (qsizetype i = 0; i < a.skipped.size(); ++i) {
        if (a.skipped[i].bytes != b.skipped[i].bytes || a.skipped[i].offset != b.skipped[i].offset
            || a.skipped[i].reason != b.skipped[i].reason)
            return false;
    }
    return true;
}

Framing framingOf(int kind)
{
    return kind <= 2 ? Framing::Rtu : (kind == 3 ? Framing::Tcp : Framing::Ascii);
}

Direction directionOf(int kind)
{
    return kind == 1 ? Direction::Request : (kind == 2 ? Direction::Response : Direction::Auto);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const int kind = data[0] % 5;
    const int chunking = data[1] & 0x03;
    const std::uint32_t seed = (data[1] >> 2) & 0x1F;
    const bool silences = (data[1] & 0x80) != 0;
    const QByteArray stream(reinterpret_cast<const char *>(data + 2), qsizetype(size - 2));

    const Output out = run(kind, stream, chunking, seed, silences);
    checkCoverage(stream, out);
    if (!silences && chunking != 3)
        check(same(out, run(kind, stream, 3, seed, false)));

    Dissection d;
    for (const StreamFrame &frame : out.frames) {
        Dissector::dissect(frame.bytes, {framingOf(kind), directionOf(kind), {}}, d);
        check(!d.fields.isEmpty());
    }
    return 0;
}
