#pragma once

#include "capture/captureoptions.h"
#include "capture/exchangesource.h"

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

    // What to do after reading a capture that had no packet on its Modbus ports.
    struct Fallback {
        enum class Action : quint8 {
            Keep,    // there was Modbus traffic (or a journal): nothing to say
            Retry,   // the ports were the defaults and Modbus was found elsewhere: read again with options
            Refuse,  // the user named the ports and Modbus was found elsewhere: message offers the options
            Nothing, // nothing looks like Modbus on any port: message says so
        };
        Action action = Action::Keep;
        CaptureOptions options;
        QString message;
    };
    // done: what the command did with the traffic, "analysed" or "exported".
    [[nodiscard]] Fallback fallback(const QCommandLineParser &parser, const CaptureOptions &options, const ExchangeSourceReport &report,
                                    const QString &done) const;

private:
    QCommandLineOption m_port;
    QCommandLineOption m_rtuPort;
    QCommandLineOption m_timeout;
};

} // namespace mbscope::app
