#pragma once

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

class QCommandLineParser;
class QTextStream;

namespace mbscope::app {

class FrameLog;

// What --print and --frame-log said.
struct PrintSettings {
    bool values = false; // --print values (poll)
    bool frames = false; // --print frames, or --frame-log FILE
    QString framePath;   // --frame-log FILE; empty: the frames go to standard error

    [[nodiscard]] bool logsFrames() const { return frames; }
};

// The options of what a command that talks prints as it goes:
//   --print frames       the live frame log (FrameLog) on standard error
//   --print values       (poll) each answer's values as it comes
//   --frame-log FILE     the live frame log to FILE instead
// --print takes several words, repeated or separated by commas ("--print values,frames").
class PrintOptions
{
public:
    // values: the command prints values as they come (poll).
    explicit PrintOptions(bool values);

    void addTo(QCommandLineParser &parser) const;
    // On error writes "mbscope COMMAND: ..." to err and returns false. force: --force was given
    // (an existing --frame-log file may be replaced).
    [[nodiscard]] bool read(const QCommandLineParser &parser, const QString &command, bool force, PrintSettings &out,
                            QTextStream &err) const;
    [[nodiscard]] bool frameLogSet(const QCommandLineParser &parser) const;

private:
    bool m_values;
    QCommandLineOption m_print;
    QCommandLineOption m_frameLog;
};

// Opens log as settings ask (nothing when they ask for no frames); false with "mbscope COMMAND:
// --frame-log: ..." on err when the file cannot be written.
[[nodiscard]] bool openFrameLog(FrameLog &log, const PrintSettings &settings, const QString &command, QTextStream &err);

} // namespace mbscope::app
