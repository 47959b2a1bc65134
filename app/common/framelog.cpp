#include "common/framelog.h"

#include "common/progressline.h"

#include "engine/transactionengine.h"
#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>

#include <cstdio>

namespace mbscope::app {

namespace {

// The verdict column is as wide as the longest name ("unsolicited").
constexpr int kVerdictWidth = 11;

void appendDigits(QByteArray &out, qint64 value, int digits)
{
    char text[12];
    for (int i = digits - 1; i >= 0; --i) {
        text[i] = char('0' + value % 10);
        value /= 10;
    }
    out.append(text, digits);
}

} // namespace

FrameLog::FrameLog(QObject *parent)
    : QObject(parent)
{
}

FrameLog::~FrameLog()
{
    close();
}

bool FrameLog::open(const QString &path, QString *error)
{
    // The local time zone is read here, not in the constructor: a command without a frame log
    // does not pay for it at start.
    const QDateTime now = QDateTime::currentDateTime();
    m_localOffsetNs = (now.toMSecsSinceEpoch() + qint64(now.offsetFromUtc()) * 1000) * 1'000'000 - monotonicNowNs();
    if (path.isEmpty()) {
        m_open = m_file.open(stderr, QIODevice::WriteOnly | QIODevice::Unbuffered);
    } else {
        m_file.setFileName(path);
        m_open = m_file.open(QIODevice::WriteOnly | QIODevice::Truncate);
    }
    if (!m_open && error)
        *error = QStringLiteral("cannot write %1: %2").arg(path.isEmpty() ? QStringLiteral("standard error") : path,
                                                           m_file.errorString());
    return m_open;
}

void FrameLog::attach(TransactionEngine *engine)
{
    engine->setFramesPublished(true);
    connect(engine, &TransactionEngine::framesLogged, this, &FrameLog::addFrames);
}

void FrameLog::addFrames(const QList<TrafficFrame> &frames, const QString &link)
{
    if (m_namesLinks && m_open && !frames.isEmpty() && link != m_lastLink) {
        m_lastLink = link;
        m_file.write("-- link " + link.toUtf8() + '\n');
    }
    add(frames);
}

void FrameLog::appendLine(QByteArray &out, const TrafficFrame &frame, qint64 localOffsetNs)
{
    const qint64 ns = frame.tNs + localOffsetNs;
    const qint64 dayNs = ((ns % (86400 * 1'000'000'000LL)) + 86400 * 1'000'000'000LL) % (86400 * 1'000'000'000LL);
    const qint64 seconds = dayNs / 1'000'000'000LL;
    appendDigits(out, seconds / 3600, 2);
    out.append(':');
    appendDigits(out, seconds / 60 % 60, 2);
    out.append(':');
    appendDigits(out, seconds % 60, 2);
    out.append('.');
    appendDigits(out, dayNs % 1'000'000'000LL / 1000, 6);
    out.append(frame.direction == TrafficDirection::Out ? " out " : " in  ");
    const char *verdict = trafficVerdictName(frame.verdict);
    out.append(verdict);
    if (!frame.bytes.isEmpty()) {
        static const char digits[] = "0123456789ABCDEF";
        const qsizetype pad = qMax(1, kVerdictWidth + 1 - int(qstrlen(verdict)));
        const qsizetype start = out.size();
        out.resize(start + pad + 3 * frame.bytes.size() - 1);
        char *p = out.data() + start;
        for (qsizetype i = 0; i < pad; ++i)
            *p++ = ' ';
        for (qsizetype i = 0; i < frame.bytes.size(); ++i) {
            if (i > 0)
                *p++ = ' ';
            const auto b = quint8(frame.bytes.at(i));
            *p++ = digits[b >> 4];
            *p++ = digits[b & 0xF];
        }
    }
    out.append('\n');
}

void FrameLog::add(const QList<TrafficFrame> &frames)
{
    if (!m_open || frames.isEmpty())
        return;
    if (m_progress && m_file.handle() == fileno(stderr))
        m_progress->clear();
    m_buffer.resize(0); // keeps its capacity for the next batch
    for (const TrafficFrame &f : frames)
        appendLine(m_buffer, f, m_localOffsetNs);
    m_lines += quint64(frames.size());
    m_file.write(m_buffer);
    m_file.flush();
}

void FrameLog::close()
{
    if (m_open)
        m_file.close();
    m_open = false;
}

} // namespace mbscope::app
