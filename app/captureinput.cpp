#include "captureinput.h"

#include "durations.h"

#include "session/capturerecovery.h"
#include "session/sessionreader.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>

namespace mbscope::app {

namespace {

// "502", "502,1502": each a port 1..65535, or the option named in the error.
bool parsePorts(const QStringList &values, const char *option, QList<quint16> *ports, QString *error)
{
    ports->clear();
    for (const QString &value : values) {
        for (const QString &item : value.split(QLatin1Char(','))) {
            bool ok = false;
            const uint port = item.trimmed().toUInt(&ok);
            if (!ok || port == 0 || port > 65535) {
                *error = QStringLiteral("--%1 '%2' is not a port: expected a number from 1 to 65535")
                             .arg(QLatin1String(option), item.trimmed());
                return false;
            }
            if (!ports->contains(quint16(port)))
                ports->append(quint16(port));
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
    if (!timeout.ok || timeout.ns <= 0) {
        *error = QStringLiteral("--timeout: %1").arg(timeout.ok ? QStringLiteral("must be more than 0") : timeout.error);
        return false;
    }
    options->timeoutNs = timeout.ns;
    return true;
}

bool CaptureInput::resolve(const QString &source, QString *path, QString *error)
{
    const QFileInfo info(source);
    if (!info.exists()) {
        *error = QStringLiteral("%1: no such file").arg(source);
        return false;
    }
    if (info.isDir()) {
        *error = QStringLiteral("%1: a directory, not a capture or journal").arg(source);
        return false;
    }
    // A session document (JSON, "{" first) stands for the traffic journal it names.
    QByteArray first;
    {
        QFile file(source);
        if (file.open(QIODevice::ReadOnly))
            first = file.read(64).trimmed();
    }
    if (!first.startsWith('{')) {
        *path = source;
        return true;
    }
    const SessionLoadResult loaded = SessionReader::load(source);
    if (!loaded.ok()) {
        *error = QStringLiteral("%1: not a session document mbscope can read:\n%2").arg(source, loaded.errorText());
        return false;
    }
    const QString journal = CaptureRecovery::journalPath(*loaded.document, source);
    if (journal.isEmpty()) {
        *error = QStringLiteral("%1: the session holds no captured traffic (no \"capture\" naming a journal)").arg(source);
        return false;
    }
    if (!QFileInfo::exists(journal)) {
        *error = QStringLiteral("%1: the session's journal %2 does not exist").arg(source, journal);
        return false;
    }
    *path = journal;
    return true;
}

} // namespace mbscope::app
