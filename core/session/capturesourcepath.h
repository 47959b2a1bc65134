#pragma once

#include <QtCore/QString>

namespace mbscope {

// Which file holds the traffic of a source a user names: the file itself for a pcap, a pcapng
// or a traffic journal; for a session document (JSON, "{" first) the journal its "capture"
// names beside it. What `mbscope analyze`, `export` and `replay` read, and what the window's
// Session menu opens.
class CaptureSourcePath
{
public:
    // False with *error when there is none: no such file, a directory, a session that cannot be
    // read (every problem listed) or that holds no capture, a journal that is not there.
    [[nodiscard]] static bool resolve(const QString &source, QString *path, QString *error);
    // True when source starts like a session document (its first non-blank byte is '{').
    [[nodiscard]] static bool isSessionDocument(const QString &source);
};

} // namespace mbscope
