#pragma once

#include "capturedirectory.h"
#include "trafficlog.h"

#include <QtCore/QMutex>
#include <QtCore/QString>

#include <functional>
#include <memory>

namespace mbscope {

// One connection's recording, always on: a TrafficLog journaled into a capture folder, in parts
// of at most rotateBytes, the folder kept under keepBytes by deleting its oldest journals, and a
// marker beside the journal being written so that a crash leaves it recoverable.
//
// Threads: made and finished in one thread; the log is shared (TrafficLog::setShared): the
// composer's engine and the window's watches and scans write into it from their threads, and
// rotation happens in whichever appends past the part's size. currentPath() may be asked from
// any thread.
struct TrafficMetadata;

class RollingCapture
{
public:
    // What a recording says it holds beyond the window and its target (trafficmetadata.h): the
    // window's tap serves masters (role server, where it listens, its routes).
    using Describe = std::function<void(TrafficMetadata &metadata)>;

    struct Policy {
        qint64 rotateBytes = qint64(64) << 20; // a journal part
        qint64 keepBytes = qint64(2) << 30;    // the whole folder
    };

    RollingCapture(const CaptureDirectory &directory, const Policy &policy);
    ~RollingCapture(); // finish()
    RollingCapture(const RollingCapture &) = delete;
    RollingCapture &operator=(const RollingCapture &) = delete;

    // Opens the first journal for a connection to target; false with *error saying why (the
    // window then works on, unrecorded, and says so).
    bool start(const QString &target, QString *error, const Describe &describe = {});
    [[nodiscard]] TrafficLog *log() { return &m_log; }
    [[nodiscard]] QString currentPath() const;
    // The journal being written goes to path (a rename: the writer carries on into it, so what
    // comes next lands there too, and later parts are made beside it; the quota only ever
    // deletes in the capture folder). False with *error when it cannot be renamed there (another
    // file system): then nothing moved.
    bool moveTo(const QString &path, QString *error);
    // Closes the journal (the engine must have let go of the log), removes the marker and keeps
    // the folder under its quota.
    void finish();

private:
    QString nextPart(const QString &closedPath);

    CaptureDirectory m_directory; // the capture folder: the quota applies here only
    CaptureDirectory m_partsDirectory; // where the next part is made
    Policy m_policy;
    TrafficLog m_log;
    QString m_target;
    QDateTime m_start;
    int m_part = 1;
    mutable QMutex m_mutex; // guards m_path and m_partsDirectory
    QString m_path;
};

} // namespace mbscope
