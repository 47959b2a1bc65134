#pragma once

#include "trafficjournal.h"

#include <QtCore/QFile>

namespace mbscope {

// One batch of a traffic journal read where it stands (trafficjournal.h gives the format;
// defined beside the reader in trafficjournal.cpp): the frames of the batch at offset of an open
// journal (where its writer's bytesWritten() stood before the batch was flushed), checked by its
// CRCs, into sink; *next: where the next batch starts. False when no whole, sound batch is there.
// TrafficArchive reads its journal back this way, a batch at a time.
bool readJournalBatch(QFile &file, qint64 offset, const TrafficJournalReader::Sink &sink, qint64 *next = nullptr);

} // namespace mbscope
