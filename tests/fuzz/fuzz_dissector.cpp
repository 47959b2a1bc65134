// libFuzzer target over the dissector: any bytes, any framing and direction, with or without a
// matching request, must give a field tree without crashing, reading out of bounds, looping or
// breaking the tree's own rules. Then every output path (JSON, table, each field's texts) runs.
//
// Input layout:
//   byte 0   bits 0-2: framing (Auto, RTU, ASCII, TCP, UDP, PDU; 6 and 7 wrap around)
//            bits 3-4: direction (Auto, Request, Response; 3 wraps around)
//            bit 5:    a matching request is given
//            bit 6:    dissect into a reused Dissection as well, and compare
//            bit 7:    write the JSON form too
//   byte 1   (with a request) request length n; the next n bytes are the request
//   the rest is the frame
#include "protocol/dissectionformat.h"
#include "protocol/dissector.h"

#include <QtCore/QJsonDocument>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace mbscope;

namespace {

constexpr Framing kFramings[] = {Framing::Auto, Framing::Rtu, Framing::Ascii, Framing::Tcp, Framing::Udp, Framing::Pdu};
constexpr Direction kDirections[] = {Direction::Auto, Direction::Request, Direction::Response};

// A broken promise is a crash for libFuzzer, with the input saved.
void check(bool condition)
{
    if (!condition)
        std::abort();
}

// The tree's own rules: a parent comes before its children, every field lies inside the frame,
// a warning or error has a message, and the chosen framing and direction are concrete.
void checkTree(const Dissection &d)
{
    const FieldTree &t = d.fields;
    check(d.framing != Framing::Auto);
    check(d.direction != Direction::Auto);
    const int frameSize = int(t.frame().size());
    for (int i = 0; i < t.size(); ++i) {
        const Field &f = t.at(i);
        check(f.parent >= -1 && f.parent < i);
        check(f.offset >= 0 && f.length >= 0 && f.offset + f.length <= frameSize);
        check(f.key != nullptr && f.name != nullptr);
        // A problem always says what is wrong.
        check(f.severity < Severity::Warning || !f.message.isEmpty());
    }
}

// The JSON form is built through QJsonObject, about 140 allocations a field (libFuzzer's
// -trace_malloc=2: three quarters of all allocations of an execution); written for every input
// it held the target to a few hundred executions a second. It runs for the inputs whose selector
// asks for it, which the fuzzer chooses like every other bit.
void exercise(const Dissection &d, bool json)
{
    const FieldTree &t = d.fields;
    qsizetype sink = 0;
    for (int i = 0; i < t.size(); ++i) {
        sink += t.display(i).size() + t.name(i).size() + t.valueText(i).size() + t.raw(i).size();
        sink += t.children(i).size();
    }
    sink += t.children(-1).size();
    sink += d.summary().size();
    if (json)
        sink += QJsonDocument(DissectionFormat::toJson(d)).toJson(QJsonDocument::Compact).size();
    sink += DissectionFormat::toTable(d).size();
    check(sink >= 0);
}

bool sameTree(const Dissection &a, const Dissection &b)
{
    if (a.framing != b.framing || a.direction != b.direction || a.fields.size() != b.fields.size())
        return false;
    for (int i = 0; i < a.fields.size(); ++i) {
        const Field &x = a.fields.at(i);
        const Field &y = b.fields.at(i);
        if (std::strcmp(x.key, y.key) != 0 || x.offset != y.offset || x.length != y.length || x.value != y.value
            || x.severity != y.severity || x.message != y.message || x.parent != y.parent || x.address != y.address)
            return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::uint8_t selector = data[0];
    DissectOptions options;
    options.framing = kFramings[(selector & 0x07) % 6];
    options.direction = kDirections[((selector >> 3) & 0x03) % 3];
    std::size_t at = 1;
    if ((selector & 0x20) && at < size) {
        const std::size_t n = std::min<std::size_t>(data[at], size - at - 1);
        options.request = QByteArray(reinterpret_cast<const char *>(data + at + 1), qsizetype(n));
        at += 1 + n;
    }
    const QByteArray frame(reinterpret_cast<const char *>(data + at), qsizetype(size - at));

    const Dissection d = Dissector::dissect(frame, options);
    checkTree(d);
    exercise(d, selector & 0x80);

    if (selector & 0x40) {
        // Reusing a Dissection must give the same tree as a fresh one, whatever it held before.
        static Dissection reused;
        Dissector::dissect(frame, options, reused);
        check(sameTree(d, reused));
    }
    return 0;
}
