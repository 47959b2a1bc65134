#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::app {

// simulate --ready-file FILE: a file that exists exactly while the simulator serves, so that a
// shell script can wait for it (`until [ -e FILE ]; do sleep 0.1; done`) instead of guessing how
// long binding takes. prepare() removes a file left by an earlier run (else a script would not
// wait) and checks that the folder can hold it; publish() writes it atomically (a temporary file
// renamed into place: a reader never sees it half written) with the listening URLs one per line,
// the ports the system chose for port 0 included; the destructor removes it again.
class ReadyFile
{
public:
    ReadyFile() = default;
    ~ReadyFile();
    ReadyFile(const ReadyFile &) = delete;
    ReadyFile &operator=(const ReadyFile &) = delete;

    // False with *error saying what is wrong with path.
    bool prepare(const QString &path, QString *error);
    bool publish(const QStringList &lines, QString *error);

private:
    QString m_path;
    bool m_published = false;
};

} // namespace mbscope::app
