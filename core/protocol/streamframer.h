#pragma once

#include "streamframe.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QList>

namespace mbscope {

// Bytes in, whole frames out, whatever the chunking: feeding a stream one byte at a time or all at
// once gives the same frames and the same skipped runs. Frames and skipped runs are queued in two
// lists, each in stream order; merging them by offset gives the order they had in the stream.
// Memory is bounded by the largest frame of the framing plus the largest chunk fed.
class StreamFramer
{
public:
    virtual ~StreamFramer();

    // timestampNs is the receive time of this chunk; every byte of it gets that time.
    void feed(QByteArrayView bytes, qint64 timestampNs = 0);
    // The link was quiet (RTU: t3.5; others: a timeout or a closed connection). Pending bytes are
    // reported as Incomplete, except that RtuFramer may emit them as a frame (see there).
    void flushOnSilence();
    // The link has been quiet since the last byte, at nowNs: flushes, unless the framing says
    // the silence is not long enough yet (RtuFramer with a baud rate: t3.5). Whether it flushed.
    virtual bool onSilence(qint64 nowNs);
    // Forget pending bytes and queued output; stream offsets start again at 0 (a new connection).
    void reset();
    // Bytes were lost just before the next ones (a capture's gap, a stream joined mid-way): as
    // reset(), then the next byte is not trusted to start a frame; the framing's own search finds
    // the next boundary (MBAP: a header confirmed by the next one; RTU: a valid CRC).
    void restartAfterGap();
    // Still looking for a frame boundary after restartAfterGap().
    [[nodiscard]] virtual bool isSearching() const { return false; }

    [[nodiscard]] QList<StreamFrame> takeFrames();
    [[nodiscard]] QList<SkippedBytes> takeSkipped();
    // Both at once into lists the caller keeps: they are cleared and swapped with the framer's,
    // so neither side allocates a list per frame (takeFrames() leaves the framer an empty list
    // that its next frame must allocate again). False when there was nothing.
    bool takeOutput(QList<StreamFrame> &frames, QList<SkippedBytes> &skipped);
    [[nodiscard]] bool hasFrames() const { return !m_frames.isEmpty(); }
    [[nodiscard]] qsizetype pendingSize() const { return m_buffer.size() - m_position; }
    // Skipped bytes of the run still open: it is reported when a frame follows, at a silence or
    // once 256 bytes long, so that a run does not depend on how the stream was chunked.
    [[nodiscard]] qsizetype openSkippedRunSize() const { return m_runOpen ? m_run.bytes.size() : 0; }
    [[nodiscard]] qint64 streamSize() const { return m_bufferOffset + m_buffer.size(); }
    // The timestamp given with the last chunk fed (0 when none).
    [[nodiscard]] qint64 lastFeedNs() const { return m_lastFeedNs; }

protected:
    StreamFramer() = default;

    // Frame or skip as much of pending() as can be decided now.
    virtual void process() = 0;
    virtual void resetState() {}
    // restartAfterGap(), after resetState(): enter the framing's search for a boundary.
    virtual void startSearch() {}
    // Called by flushOnSilence(), with or without bytes pending; must consume them all.
    virtual void flushPending();

    [[nodiscard]] QByteArrayView pending() const { return QByteArrayView(m_buffer).sliced(m_position); }
    [[nodiscard]] qint64 pendingOffset() const { return m_bufferOffset + m_position; }
    // Take the first length pending bytes as a frame. Closes the open skipped run first.
    void emitFrame(qsizetype length, FrameStatus status = FrameStatus::Valid, const QString &problem = {});
    // Drop the first length pending bytes. They join the open run when it has the same reason, or
    // always when extendRun is set (one resynchronisation reported as one run).
    void skip(qsizetype length, SkipReason reason, bool extendRun = false);
    void closeSkippedRun();

private:
    struct Stamp {
        qint64 offset;
        qint64 ns;
    };
    [[nodiscard]] qint64 stampAt(qint64 offset) const;
    void compact();

    QByteArray m_buffer;
    qsizetype m_position = 0;  // first pending byte in m_buffer
    qint64 m_bufferOffset = 0; // stream offset of m_buffer[0]
    qint64 m_lastFeedNs = 0;
    QList<Stamp> m_stamps;     // one per fed chunk still in m_buffer, by offset
    SkippedBytes m_run;        // the open skipped run, when m_runOpen
    bool m_runOpen = false;
    QList<StreamFrame> m_frames;
    QList<SkippedBytes> m_skipped;
};

} // namespace mbscope
