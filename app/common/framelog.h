#pragma once

#include "exchange/trafficentry.h"

#include <QtCore/QByteArray>
#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {
class TransactionEngine;
}

namespace mbscope::app {

class ProgressLine;

// The live frame log of --print frames and --frame-log FILE: every frame as the engine logs it,
// one line each, written as the engine's batches arrive (at most ~30 a second) and flushed after
// each, so that a killed command keeps its lines:
//   13:05:12.345678 out sent        01 03 00 79 00 16 15 DD
//   13:05:12.351234 in  ok          01 03 2C 00 45 ...
//   13:05:13.351234 in  timeout
// local time with microseconds (the frame's own monotonic time stamp: written, or first byte
// read), direction, the engine's verdict, and the bytes in hex; an answer that never came is an
// "in" line with its verdict and no bytes. Formatting runs in the receiving (main) thread, never
// on the engine's receive path.
//
// The frames come from where the engines record them for --record (EngineRecorder, published as
// framesLogged batches by TransactionEngine, ProbeChannel, WatchRunner, PlanRunner...): any of
// those signals connects to addFrames. A command that talks over several links (watch, scan
// --line) calls setNamesLinks(true): a line "-- link URL" then comes before the frames of a link
// other than the previous batch's.
class FrameLog : public QObject
{
    Q_OBJECT
public:
    explicit FrameLog(QObject *parent = nullptr);
    ~FrameLog() override;

    // To standard error (path empty) or to the file, created or replaced.
    [[nodiscard]] bool open(const QString &path, QString *error);
    [[nodiscard]] bool isOpen() const { return m_open; }
    // The engine publishes its frames to this log from now on.
    void attach(TransactionEngine *engine);
    void add(const QList<mbscope::TrafficFrame> &frames);
    // The signature of the framesLogged signals: connect one to this.
    void addFrames(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void setNamesLinks(bool names) { m_namesLinks = names; }
    // A progress line on the same terminal, cleared before each batch (it comes back with its next
    // show()).
    void setProgressLine(ProgressLine *line) { m_progress = line; }
    void close();
    [[nodiscard]] quint64 lines() const { return m_lines; }

    // Appends one frame's line (with its newline) to out, for a wall-clock offset (wall ns minus
    // monotonic ns) that includes the local time zone's; the hex is written in place, with no
    // allocation beyond out's own growth.
    static void appendLine(QByteArray &out, const TrafficFrame &frame, qint64 localOffsetNs);

private:
    QFile m_file;
    bool m_open = false;
    qint64 m_localOffsetNs = 0;
    quint64 m_lines = 0;
    QByteArray m_buffer;
    bool m_namesLinks = false;
    ProgressLine *m_progress = nullptr;
    QString m_lastLink;
};

} // namespace mbscope::app
