#pragma once

#include "capture/captureoptions.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QList>
#include <QtCore/QString>

class QCommandLineParser;

namespace mbscope::app {

// The options analyze and export share to read a capture: which ports carry Modbus and how long
// a request may wait for its answer.
class CaptureInput
{
public:
    CaptureInput();

    void addTo(QCommandLineParser &parser) const;
    // False with *error naming the option at fault.
    [[nodiscard]] bool read(const QCommandLineParser &parser, CaptureOptions *options, QString *error) const;

    // The file to read for a source given on the command line: the file itself (a pcap, a
    // pcapng or a traffic journal), or for a session document the journal its "capture" names.
    // False with *error when there is none (no such file, a session without a capture...).
    [[nodiscard]] static bool resolve(const QString &source, QString *path, QString *error);

private:
    QCommandLineOption m_port;
    QCommandLineOption m_rtuPort;
    QCommandLineOption m_timeout;
};

} // namespace mbscope::app
