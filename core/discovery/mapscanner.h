#pragma once

#include "mapscansettings.h"
#include "probechannel.h"
#include "registermap.h"
#include "job/jobend.h"
#include "job/jobprogress.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>

#include <optional>

namespace mbscope {

// Which addresses of each table a unit has, the largest quantity each read function takes, and
// which optional functions it answers, in few requests:
// - the quantity limit: the spec's maximum (125 registers, 2000 bits) is asked at the first address;
//   exception 03 (V1.1b3, 6.3: "quantity of registers" is checked before the address) then narrows
//   it down by bisection;
// - a block: found by a one-address read that answers, its end by galloping (1, 2, 4... addresses)
//   then bisection on where exception 02 starts, a block longer than one read taken in reads of the
//   largest quantity. Every address of a block is read, so the map carries the values too;
// - between blocks, one one-address read per address: exception 02 says nothing about the
//   addresses after it, so nothing can be skipped without missing a lone register.
// Only reads, and for 17 a request with write quantity 0, which a device refuses (03) before it
// writes (V1.1b3, 6.17); 15 and 16 are never sent. Bounded by a request count and a time limit.
// run() runs local event loops until done; stop() (from a slot or a signal) ends it early.
class MapScanner : public QObject
{
    Q_OBJECT
public:
    explicit MapScanner(QObject *parent = nullptr);

    // The map, or nullopt with settings.problem() unusable. end() says how it ended.
    [[nodiscard]] std::optional<RegisterMap> run(const MapScanSettings &settings);
    void stop()
    {
        m_stopRequested = true;
        m_channel->cancel();
    }
    [[nodiscard]] JobEnd end() const { return m_end; }
    // The link's own words when it failed (JobEnd::LinkError), else empty.
    [[nodiscard]] QString linkProblem() const { return m_linkProblem; }
    [[nodiscard]] ProbeChannel *channel() { return m_channel; }

Q_SIGNALS:
    void progressChanged(const mbscope::JobProgress &progress);

private:
    enum class Reply : quint8 { Ok, IllegalAddress, IllegalQuantity, IllegalFunction, OtherException, Silent, Bad };
    struct ReadReply {
        Reply reply = Reply::Silent;
        quint8 exceptionCode = 0;
        QList<quint16> values;
    };
    [[nodiscard]] bool mayContinue();
    [[nodiscard]] std::optional<ProbeChannel::Answer> ask(const QByteArray &pdu);
    [[nodiscard]] ReadReply read(quint8 function, int address, int quantity);
    void mapTable(TableMap &table);
    [[nodiscard]] int findMaxQuantity(TableMap &table, int specMax);
    // From a first address known to exist: the block's values, reading on until 02.
    [[nodiscard]] MapBlock extendBlock(TableMap &table, int address, QList<quint16> firstValues);
    void probeOptional(RegisterMap &map);
    void report(int tableIndex, int address);

    ProbeChannel *m_channel;
    MapScanSettings m_settings;
    QElapsedTimer m_clock;
    int m_requests = 0;
    bool m_stopRequested = false;
    JobEnd m_end = JobEnd::Completed;
    QString m_linkProblem;
    int m_tableIndex = 0;
};

} // namespace mbscope
