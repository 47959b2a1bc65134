#pragma once

#include "exchange/trafficentry.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QList>
#include <QtCore/QString>

#include <vector>

namespace mbscope {

// The traffic monitor's rows, compact: a 48-byte record per frame and the frame's bytes packed in
// 1 MiB chunks, no QString and no allocation per row, so a million frames cost about 60 MB. Text
// is made by the model when a cell is painted. What the list needs at a glance (unit, function,
// the request an answer belongs to, the latency) is worked out once, when a frame is appended.
class TrafficStore
{
public:
    struct Row {
        qint64 tNs = 0;            // monotonic ns: written, or the answer's first (or last) byte
        quint64 transactionId = 0; // 0: no transaction (garbage, unsolicited)
        quint64 byteOffset = 0;    // chunk << 32 | offset in chunk
        quint32 length = 0;
        qint32 latencyUs = -1;     // answers: request written to answer; -1 none
        quint32 pairDelta = 0;     // rows to the paired frame: back to the request (in), on to
                                   // the answer (out); 0: none
        quint16 link = 0;
        TrafficDirection direction = TrafficDirection::Out;
        TrafficVerdict verdict = TrafficVerdict::Sent;
        quint8 unit = 0;
        quint8 function = 0;
        quint8 flags = 0; // HasUnit | HasFunction

        [[nodiscard]] bool hasUnit() const { return flags & HasUnit; }
        [[nodiscard]] bool hasFunction() const { return flags & HasFunction; }
    };
    enum RowFlag : quint8 { HasUnit = 1, HasFunction = 2 };

    // An answer is paired with the latest request of its transaction within this many rows back:
    // enough for deep pipelining, bounded so a lost request never costs a scan of the whole list.
    static constexpr int kPairWindow = 4096;
    static constexpr qsizetype kChunkBytes = qsizetype(1) << 20;

    // Names a link id (TrafficLog::addLink's ids in TrafficFrame::link); the URL gives the framing.
    void setLinkName(quint16 link, const QString &url);
    // The id of a link by URL, added when new.
    [[nodiscard]] quint16 linkId(const QString &url);
    [[nodiscard]] QString linkName(quint16 link) const;
    [[nodiscard]] Framing linkFraming(quint16 link) const; // Auto when the link is not named
    [[nodiscard]] const QStringList &linkNames() const { return m_linkNames; }

    // latencyNs -1: paired with its request here (an answer's first byte minus the request's time).
    void append(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict,
                quint64 transactionId, QByteArrayView bytes, qint64 latencyNs = -1);
    void clear();
    // Drops the oldest count rows (and the byte chunks only they used).
    void removeFront(qsizetype count);

    [[nodiscard]] qsizetype size() const { return qsizetype(m_rows.size()); }
    [[nodiscard]] const Row &row(qsizetype index) const { return m_rows[size_t(index)]; }
    [[nodiscard]] QByteArrayView bytes(qsizetype index) const;
    // The request an answer belongs to, or the answer a request got; -1 when none is known.
    [[nodiscard]] qsizetype pairedRow(qsizetype index) const;
    [[nodiscard]] qint64 latencyNs(qsizetype index) const;

    // Unit and function code of a frame in a framing (Auto: guessed from the bytes).
    [[nodiscard]] static Row keysOf(QByteArrayView bytes, Framing framing);

    // Heap bytes held: rows (capacity), byte chunks, link names.
    [[nodiscard]] std::size_t memoryBytes() const;

private:
    [[nodiscard]] quint64 storeBytes(QByteArrayView bytes);
    void pair(qsizetype index);

    std::vector<Row> m_rows;
    std::vector<QByteArray> m_chunks; // each reserved to kChunkBytes (or the frame, when larger)
    quint64 m_chunkBase = 0;          // chunks dropped by removeFront: row chunk numbers count them
    QStringList m_linkNames;          // by link id; empty: not named
    std::vector<Framing> m_linkFramings;
    std::vector<bool> m_linkDelimited; // delimited frames: no unit, no function code
};

} // namespace mbscope
