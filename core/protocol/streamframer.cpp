#include "streamframer.h"

#include <utility>

namespace mbscope {

namespace {
constexpr qsizetype kMaxRun = 256;
constexpr qsizetype kCompactAt = 1024;
} // namespace

const char *skipReasonName(SkipReason reason)
{
    switch (reason) {
    case SkipReason::NoFrameStart: return QT_TRANSLATE_NOOP("mbscope::Field", "no frame start");
    case SkipReason::InvalidHeader: return QT_TRANSLATE_NOOP("mbscope::Field", "invalid MBAP header");
    case SkipReason::ChecksumMismatch: return QT_TRANSLATE_NOOP("mbscope::Field", "CRC mismatch");
    case SkipReason::ImpossibleFunction: return QT_TRANSLATE_NOOP("mbscope::Field", "impossible function code");
    case SkipReason::NoLengthRule: return QT_TRANSLATE_NOOP("mbscope::Field", "function code without a length rule while resynchronising");
    case SkipReason::Abandoned: return QT_TRANSLATE_NOOP("mbscope::Field", "frame restarted by ':'");
    case SkipReason::TooLong: return QT_TRANSLATE_NOOP("mbscope::Field", "frame too long");
    case SkipReason::Incomplete: return QT_TRANSLATE_NOOP("mbscope::Field", "incomplete frame at silence");
    case SkipReason::AfterGap: return QT_TRANSLATE_NOOP("mbscope::Field", "rest of a frame cut by a gap");
    }
    return QT_TRANSLATE_NOOP("mbscope::Field", "unknown reason");
}

StreamFramer::~StreamFramer() = default;

void StreamFramer::feed(QByteArrayView bytes, qint64 timestampNs)
{
    if (bytes.isEmpty())
        return;
    if (timestampNs != 0 || !m_stamps.isEmpty()) {
        if (m_stamps.isEmpty() || m_stamps.back().ns != timestampNs)
            m_stamps.append(Stamp{streamSize(), timestampNs});
    }
    m_lastFeedNs = timestampNs;
    m_buffer.append(bytes.data(), bytes.size());
    process();
    compact();
}

void StreamFramer::flushOnSilence()
{
    flushPending();
    closeSkippedRun();
    compact();
}

bool StreamFramer::onSilence(qint64 nowNs)
{
    Q_UNUSED(nowNs);
    flushOnSilence();
    return true;
}

void StreamFramer::flushPending()
{
    if (pendingSize() > 0)
        skip(pendingSize(), SkipReason::Incomplete);
}

void StreamFramer::reset()
{
    m_buffer.resize(0);
    m_position = 0;
    m_bufferOffset = 0;
    m_lastFeedNs = 0;
    m_stamps.clear();
    m_run = {};
    m_runOpen = false;
    m_frames.clear();
    m_skipped.clear();
    resetState();
}

void StreamFramer::restartAfterGap()
{
    reset();
    startSearch();
}

QList<StreamFrame> StreamFramer::takeFrames()
{
    return std::exchange(m_frames, {});
}

QList<SkippedBytes> StreamFramer::takeSkipped()
{
    return std::exchange(m_skipped, {});
}

bool StreamFramer::takeOutput(QList<StreamFrame> &frames, QList<SkippedBytes> &skipped)
{
    frames.clear();
    skipped.clear();
    if (m_frames.isEmpty() && m_skipped.isEmpty())
        return false;
    m_frames.swap(frames);
    m_skipped.swap(skipped);
    return true;
}

void StreamFramer::emitFrame(qsizetype length, FrameStatus status, const QString &problem)
{
    closeSkippedRun();
    StreamFrame frame;
    frame.offset = pendingOffset();
    frame.bytes = pending().first(length).toByteArray();
    frame.firstByteNs = stampAt(frame.offset);
    frame.lastByteNs = stampAt(frame.offset + length - 1);
    frame.status = status;
    frame.problem = problem;
    m_frames.append(std::move(frame));
    m_position += length;
}

void StreamFramer::skip(qsizetype length, SkipReason reason, bool extendRun)
{
    while (length > 0) {
        if (m_runOpen && (m_run.bytes.size() >= kMaxRun || (!extendRun && m_run.reason != reason)))
            closeSkippedRun();
        if (!m_runOpen) {
            m_run.offset = pendingOffset();
            m_run.reason = reason;
            m_runOpen = true;
        }
        const qsizetype take = qMin(length, kMaxRun - m_run.bytes.size());
        m_run.bytes.append(pending().first(take));
        m_position += take;
        length -= take;
    }
}

void StreamFramer::closeSkippedRun()
{
    if (!m_runOpen)
        return;
    m_skipped.append(std::exchange(m_run, {}));
    m_runOpen = false;
}

qint64 StreamFramer::stampAt(qint64 offset) const
{
    qint64 ns = 0;
    for (const Stamp &stamp : m_stamps) {
        if (stamp.offset > offset)
            break;
        ns = stamp.ns;
    }
    return ns;
}

void StreamFramer::compact()
{
    // Move the pending bytes to the front only now and then, so that the buffer's memory is reused
    // and no byte is moved more than a few times.
    if (m_position == m_buffer.size()) {
        m_bufferOffset += m_buffer.size();
        m_buffer.resize(0);
        m_position = 0;
    } else if (m_position >= kCompactAt || m_position > m_buffer.size() / 2) {
        m_buffer.remove(0, m_position);
        m_bufferOffset += m_position;
        m_position = 0;
    }
    const qint64 first = pendingOffset();
    while (m_stamps.size() > 1 && m_stamps.at(1).offset <= first)
        m_stamps.removeFirst();
}

} // namespace mbscope
