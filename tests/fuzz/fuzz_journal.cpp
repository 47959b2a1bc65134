// libFuzzer target over traffic journals (trafficjournal.h, versions 1 and 2): any bytes as a
// journal file go through the reader, the metadata parser and the journal's exchange reader
// without a crash, a hang or a sanitizer report; and what comes out is consistent: frames only
// from complete batches, the good bytes inside the file, every exchange with a request or an
// answer.
//
// Input layout: the bytes are the file (written to a temporary file: the reader maps a path).
#include "capture/journalexchangereader.h"
#include "traffic/trafficjournal.h"
#include "traffic/trafficmetadata.h"

#include <QtCore/QTemporaryFile>

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
    QTemporaryFile file;
    if (!file.open())
        return 0;
    file.write(reinterpret_cast<const char *>(data), qint64(size));
    file.flush();
    const QString path = file.fileName();

    quint64 frames = 0;
    const TrafficJournalRecovery r = TrafficJournalReader::read(
        path, [&frames](const TrafficEntry &e) { frames += e.bytes.size() >= 0 ? 1 : 0; },
        [](const TrafficJournalNote &note) { check(note.json.size() >= 0); });
    check(frames == r.frames);
    check(r.goodBytes <= r.fileBytes && r.fileBytes == qint64(size));
    check(r.metadata.isEmpty() || r.version >= 2);
    if (!r.metadata.isEmpty()) {
        TrafficMetadata m;
        QString error;
        if (TrafficMetadata::fromJson(r.metadata, &m, &error)) {
            TrafficMetadata again;
            check(TrafficMetadata::fromJson(m.toUtf8(), &again, &error));
        }
    }
    const JournalExchangeReader::Result x = JournalExchangeReader::read(path, [](const CaptureExchange &e) {
        check(!e.transaction.request.isEmpty() || !e.transaction.response.isEmpty());
    });
    check(x.recovery.frames == r.frames);
    return 0;
}
