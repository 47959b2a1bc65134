#pragma once

#include "blocksamples.h"

#include "discovery/probechannel.h"
#include "discovery/registermap.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

// A block to sample: read function 01-04, first address, how many addresses.
struct BlockRequest {
    quint8 function = 3;
    quint16 address = 0;
    int count = 1;
};

struct SampleSettings {
    LinkUrl url;
    quint8 unit = 1;
    QList<BlockRequest> blocks;
    int samples = 30;          // rounds: every block read once per round
    int intervalMs = 1000;     // from the start of one round to the start of the next
    int timeoutMs = 1000;
    int maxQuantity = 125;     // registers per read (bits: 2000); longer blocks take several reads

    // The blocks a map scan found, each read whole (in reads of the largest quantity the scan
    // measured for registers): what `mbscope infer` samples after its scan, and the window's Infer.
    void takeBlocks(const RegisterMap &map);
};

// Reads the blocks again and again through a ProbeChannel (a TransactionEngine of its own), one
// request at a time, reads only (01-04): inference's samples. A read that fails (exception,
// timeout) loses that block's sample of the round and is counted. run() runs local event loops
// until done; stop() ends it after the request in flight.
class BlockSampler : public QObject
{
    Q_OBJECT
public:
    explicit BlockSampler(QObject *parent = nullptr);

    [[nodiscard]] QList<BlockSamples> run(const SampleSettings &settings);
    void stop();
    [[nodiscard]] ProbeChannel *channel() { return m_channel; }
    // Why the last run read nothing at all (the first failure), or empty.
    [[nodiscard]] QString problem() const { return m_problem; }
    // A read of the last run failed on the link (it could not be opened, or it broke).
    [[nodiscard]] bool linkFailed() const { return m_linkFailed; }

Q_SIGNALS:
    void roundDone(int done, int total);

private:
    [[nodiscard]] bool readBlock(const SampleSettings &settings, const BlockRequest &block, QList<quint16> *words);

    ProbeChannel *m_channel;
    bool m_stopRequested = false;
    bool m_linkFailed = false;
    QString m_problem;
};

} // namespace mbscope
