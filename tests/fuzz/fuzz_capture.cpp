// libFuzzer target over the capture path: any bytes as a capture file (pcap or pcapng) go
// through the reader, the packet decoder, TCP reassembly, the framers and the pairer without a
// crash, a hang or a sanitizer report; and what comes out is consistent: every exchange has a
// request or an answer, a timeout has no answer and a late record has one, the reader's
// figures stay inside the file.
//
// Input layout: the bytes are the file. Port 502 is MBAP, 4001 RTU (the seeds use both).
#include "capture/exchangesource.h"

#include <QtCore/QByteArrayView>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    CaptureOptions options;
    options.mbapPorts = {502};
    options.rtuPorts = {4001};
    const QByteArrayView bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const ExchangeSourceReport report = ExchangeSource::readCapture(bytes, options, [](const CaptureExchange &e) {
        const Transaction &t = e.transaction;
        check(!t.request.isEmpty() || !t.response.isEmpty());
        if (e.kind == CaptureExchange::Kind::UnmatchedResponse)
            check(t.request.isEmpty() && !t.response.isEmpty());
        else
            check(!t.request.isEmpty());
        if (t.status == TransactionStatus::Timeout || t.status == TransactionStatus::Broadcast)
            check(t.response.isEmpty());
        if (t.status == TransactionStatus::Late)
            check(!t.response.isEmpty());
    });
    check(report.file.goodBytes <= qint64(size));
    check(report.file.errorOffset <= qint64(size));
    check(report.isComplete() == report.error.isEmpty() || !report.isReadable());
    return 0;
}
