#include "capture/captureinput.h"

#include "time/duration.h"

#include "capture/captureports.h"
#include "session/capturesourcepath.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QStringList>

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
                               "(default 1s, as the engine's); one the capture ends sooner after is unanswered at its end."),
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

CaptureInput::Fallback CaptureInput::fallback(const QCommandLineParser &parser, const CaptureOptions &options,
                                              const ExchangeSourceReport &report, const QString &done) const
{
    Fallback f;
    if (report.kind != ExchangeSourceReport::Kind::Capture || report.frames.modbusPackets > 0)
        return f;
    const QList<quint16> asked = options.mbapPorts + options.rtuPorts;
    const QString where = QStringLiteral("no Modbus traffic on %1 %2")
                              .arg(asked.size() == 1 ? QStringLiteral("port") : QStringLiteral("ports"), CapturePorts::format(asked));
    if (report.otherModbusPorts.empty()) {
        f.action = Fallback::Action::Nothing;
        f.message = where + QStringLiteral(", and none that looks like Modbus TCP or RTU on any other port");
        return f;
    }
    f.options = options;
    f.options.mbapPorts.clear();
    f.options.rtuPorts.clear();
    QStringList found;
    for (const ModbusPortFinder::Found &p : report.otherModbusPorts) {
        QList<quint16> &ports = p.framing == Framing::Rtu ? f.options.rtuPorts : f.options.mbapPorts;
        if (!ports.contains(p.port))
            ports.append(p.port);
        found.append(p.description());
    }
    QStringList optionText;
    if (!f.options.mbapPorts.isEmpty())
        optionText.append(QStringLiteral("--port ") + CapturePorts::format(f.options.mbapPorts).remove(QLatin1Char(' ')));
    if (!f.options.rtuPorts.isEmpty())
        optionText.append(QStringLiteral("--rtu-port ") + CapturePorts::format(f.options.rtuPorts).remove(QLatin1Char(' ')));
    const QString foundText = found.size() == 1 ? found.constFirst()
                                                : found.mid(0, found.size() - 1).join(QStringLiteral(", ")) + QStringLiteral(" and ") + found.constLast();
    if (parser.isSet(m_port) || parser.isSet(m_rtuPort)) {
        // Ports the user named are never overridden: the message offers the ones found.
        f.action = Fallback::Action::Refuse;
        f.message = QStringLiteral("%1; found %2: %3 to use %4").arg(where, foundText, optionText.join(QLatin1Char(' ')),
                                                                     found.size() == 1 ? QStringLiteral("it") : QStringLiteral("them"));
        return f;
    }
    f.action = Fallback::Action::Retry;
    f.message = QStringLiteral("%1; found %2 and %3 %4 (%5 to say so)")
                    .arg(where, foundText, done, found.size() == 1 ? QStringLiteral("that") : QStringLiteral("those"),
                         optionText.join(QLatin1Char(' ')));
    return f;
}

bool CaptureInput::resolve(const QString &source, QString *path, QString *error)
{
    return CaptureSourcePath::resolve(source, path, error);
}

} // namespace mbscope::app
