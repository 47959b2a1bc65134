#include "captureinput.h"

#include "time/duration.h"

#include "capture/captureports.h"
#include "session/capturesourcepath.h"

#include <QtCore/QCommandLineParser>

namespace mbscope::app {

namespace {

// "502", "502,1502", repeated options: each a port 1..65535, or the option named in the error.
bool parsePorts(const QStringList &values, const char *option, QList<quint16> *ports, QString *error)
{
    ports->clear();
    for (const QString &value : values) {
        QList<quint16> parsed;
        if (!CapturePorts::parse(value, &parsed, error)) {
            *error = QStringLiteral("--%1 %2").arg(QLatin1String(option), *error);
            return false;
        }
        for (quint16 port : parsed) {
            if (!ports->contains(port))
                ports->append(port);
        }
    }
    return true;
}

} // namespace

CaptureInput::CaptureInput()
    : m_port(QStringLiteral("port"),
             QStringLiteral("Server port(s) carrying Modbus TCP (MBAP over TCP) and Modbus UDP, comma-separated or repeated "
                            "(default 502)."),
             QStringLiteral("port"))
    , m_rtuPort(QStringLiteral("rtu-port"),
                QStringLiteral("Server port(s) carrying RTU frames over TCP or UDP (a serial device server, e.g. 4001)."),
                QStringLiteral("port"))
    , m_timeout(QStringLiteral("timeout"),
                QStringLiteral("A request unanswered this long in capture time is a timeout, and a later answer late "
                               "(default 1s, as the engine's)."),
                QStringLiteral("duration"), QStringLiteral("1s"))
{
}

void CaptureInput::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_port, m_rtuPort, m_timeout});
}

bool CaptureInput::read(const QCommandLineParser &parser, CaptureOptions *options, QString *error) const
{
    if (parser.isSet(m_port) && !parsePorts(parser.values(m_port), "port", &options->mbapPorts, error))
        return false;
    if (parser.isSet(m_rtuPort) && !parsePorts(parser.values(m_rtuPort), "rtu-port", &options->rtuPorts, error))
        return false;
    const DurationResult timeout = parseDuration(parser.value(m_timeout));
    if (!timeout.ok() || timeout.ns <= 0) {
        *error = QStringLiteral("--timeout: %1").arg(timeout.ok() ? QStringLiteral("must be more than 0") : timeout.error);
        return false;
    }
    options->timeoutNs = timeout.ns;
    return true;
}

bool CaptureInput::resolve(const QString &source, QString *path, QString *error)
{
    return CaptureSourcePath::resolve(source, path, error);
}

} // namespace mbscope::app
