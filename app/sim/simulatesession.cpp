#include "sim/simulatesession.h"

#include "protocol/hexnumber.h"
#include "protocol/adubuilder.h"
#include "protocol/delimitedframer.h"
#include "protocol/functioncode.h"
#include "sim/profileapplier.h"
#include "sim/simendpoint.h"
#include "sim/simexchange.h"
#include "sim/simunit.h"

#include <QtCore/QDateTime>
#include <QtCore/QRegularExpression>
#include <QtCore/QTextStream>

#include <memory>

namespace mbscope::app {

namespace {

QString joinIds(const QList<quint8> &ids)
{
    QStringList parts;
    for (quint8 id : ids)
        parts << QString::number(id);
    return parts.join(QStringLiteral(", "));
}

bool isRequest(SimLogEntry::Verdict v)
{
    using V = SimLogEntry::Verdict;
    return v == V::Answered || v == V::Exception || v == V::NoAnswer || v == V::UnknownUnit
           || v == V::ChecksumError || v == V::Malformed;
}

} // namespace

SimulateSession::SimulateSession(QTextStream &out, const Options &options, QObject *parent)
    : QObject(parent), m_out(out), m_options(options)
{
    connect(&m_recorder, &SimFaultPlanRecorder::recorded, this, [this](const SimTrafficRecord &record) {
        finish(record.entry, record.plan ? &*record.plan : nullptr);
    });
    connect(&m_scripts, &SimScriptDriver::logged, this, &SimulateSession::printScriptLine);
    connect(&m_summaryTimer, &QTimer::timeout, this, [this] {
        m_out << QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")) << "  " << summary() << Qt::endl;
    });
}

SimulateSession::~SimulateSession()
{
    for (const QString &line : std::as_const(m_heldLines)) // never started: the load's lines are still worth seeing
        m_out << line << '\n';
    m_out.flush();
    stop();
}

bool SimulateSession::load(const DeviceProfile &profile, const std::optional<FaultRuleSet> &faults, QString *error)
{
    const QList<SimUnit *> units = ProfileApplier::createUnits(profile, nullptr, error);
    if (units.isEmpty() && !profile.units.isEmpty())
        return false;
    for (SimUnit *unit : units) {
        const quint8 id = unit->id();
        SimUnit *adopted = m_sim.adoptUnit(std::unique_ptr<SimUnit>(unit));
        if (!adopted) {
            *error = QStringLiteral("unit %1: the id is taken or invalid").arg(id);
            return false;
        }
        m_units.append(adopted);
    }
    ProfileApplier::configure(&m_injector, profile);
    m_sim.setLimits(profile.limits);
    m_sim.setLineTable(profile.delimited);
    m_endpointOptions = ProfileApplier::endpointOptions(profile);
    if (faults)
        m_injector.setRules(*faults);
    m_driver.attach(profile, m_units);
    QStringList problems;
    if (!m_scripts.attach(profile, &m_sim, &problems)) {
        *error = problems.join(QLatin1Char('\n'));
        return false;
    }
    return true;
}

bool SimulateSession::listen(const QStringList &urls, QString *error)
{
    for (const QString &url : urls) {
        QString why;
        SimEndpoint *endpoint = m_sim.listen(url, m_endpointOptions, &why);
        if (!endpoint) {
            *error = why.isEmpty() ? url + QStringLiteral(": cannot listen") : why;
            if (why.contains(QLatin1String("in use"), Qt::CaseInsensitive))
                *error += QStringLiteral("\n(another program serves that port: choose another with --listen, e.g. --listen %1)")
                              .arg(QString(url).replace(QRegularExpression(QStringLiteral(":(\\d+)(?=[/?]|$)")),
                                                        QStringLiteral(":0")));
            return false;
        }
        m_framings.insert(endpoint->name(), endpoint->framing());
        if (endpoint->url().delimited.enabled)
            m_delimited.insert(endpoint->name());
    }
    return true;
}

void SimulateSession::setTrafficLog(TrafficLog *log)
{
    m_sim.setTrafficLog(log);
}

void SimulateSession::setRemote(SimRemote *remote)
{
    m_sim.setRemote(remote);
    m_remote = remote != nullptr;
}

void SimulateSession::start()
{
    m_started = true;
    for (const QString &line : std::as_const(m_heldLines))
        m_out << line << '\n';
    m_heldLines.clear();
    m_out.flush();
    m_elapsed.start();
    m_driver.start();
    m_scripts.start();
    if (m_options.quiet && m_options.summaryIntervalMs > 0)
        m_summaryTimer.start(m_options.summaryIntervalMs);
}

void SimulateSession::stop()
{
    m_summaryTimer.stop();
    m_driver.stop();
    m_scripts.stop();
    m_sim.closeAll();
}

QStringList SimulateSession::endpointDescriptions() const
{
    QStringList lines;
    for (SimEndpoint *endpoint : m_sim.endpoints()) {
        const QList<quint8> ids = endpoint->options().units.isEmpty() ? m_sim.unitIds() : endpoint->options().units;
        lines << QStringLiteral("%1 (unit%2 %3)").arg(endpoint->name(), ids.size() == 1 ? QString() : QStringLiteral("s"),
                                                     joinIds(ids));
    }
    return lines;
}

QString SimulateSession::summary() const
{
    const double seconds = m_elapsed.isValid() ? double(m_elapsed.elapsed()) / 1000.0 : 0.0;
    int open = 0;
    for (SimEndpoint *endpoint : m_sim.endpoints())
        open += endpoint->connectionCount();
    const Counts &c = m_counts;
    return QStringLiteral("%1 requests in %2 s (%3/s): %4 answered, %5 exceptions, %6 unknown unit, %7 without answer, "
                          "%8 dropped by fault, %9 changed by faults, %10 malformed; %11 connections (%12 open, %13 refused)")
        .arg(c.requests)
        .arg(seconds, 0, 'f', 1)
        .arg(seconds > 0 ? double(c.requests) / seconds : 0.0, 0, 'f', 0)
        .arg(c.answered)
        .arg(c.exceptions)
        .arg(c.unknownUnit)
        .arg(c.noAnswer)
        .arg(c.droppedByFault)
        .arg(c.faulted)
        .arg(c.malformed)
        .arg(c.connections)
        .arg(open)
        .arg(c.refused);
}

void SimulateSession::finish(const SimLogEntry &entry, const FaultPlan *plan)
{
    count(entry, plan);
    if (!m_options.quiet)
        printLine(entry, plan);
}

void SimulateSession::count(const SimLogEntry &entry, const FaultPlan *plan)
{
    using V = SimLogEntry::Verdict;
    Counts &c = m_counts;
    if (isRequest(entry.verdict))
        ++c.requests;
    const bool dropped = plan && (plan->drop || plan->closeBefore);
    if (dropped) {
        ++c.droppedByFault;
        return;
    }
    if (plan && !plan->faults.isEmpty())
        ++c.faulted;
    switch (entry.verdict) {
    case V::Answered: ++c.answered; break;
    case V::Exception: ++c.exceptions; break;
    case V::NoAnswer: ++c.noAnswer; break;
    case V::UnknownUnit: ++c.unknownUnit; break;
    case V::ChecksumError:
    case V::Malformed:
    case V::Garbage: ++c.malformed; break;
    case V::ConnectionOpened: ++c.connections; break;
    case V::ConnectionRefused: ++c.refused; break;
    case V::ConnectionClosed: break;
    }
}

Framing SimulateSession::framingOf(const QString &endpoint) const
{
    return m_framings.value(endpoint, Framing::Tcp);
}

QString SimulateSession::verdictText(const SimLogEntry &entry, const FaultPlan *plan) const
{
    using V = SimLogEntry::Verdict;
    const QString faults = plan ? plan->faults.join(QStringLiteral(", ")) : QString();
    if (plan && (plan->drop || plan->closeBefore))
        return QStringLiteral("dropped by fault (%1)%2").arg(faults, plan->closeBefore ? QStringLiteral(": connection closed") : QString());
    QString text;
    switch (entry.verdict) {
    case V::Answered:
        text = QStringLiteral("answered");
        if (m_remote && !entry.reason.isEmpty())
            text += QStringLiteral(" (%1)").arg(entry.reason); // "device 1.9 ms"
        break;
    case V::Exception: {
        const AduParts response = AduBuilder::parse(entry.response, framingOf(entry.endpoint));
        const quint8 code = response.pdu.size() >= 2 ? quint8(response.pdu.at(1)) : 0;
        text = QStringLiteral("exception %1 %2").arg(hexNumber(code, 2)).arg(QLatin1String(exceptionName(code)));
        // Why: a device limit with its figures ("refused by minGapMs: 4.1 ms after the last
        // request taken, minGapMs is 50"), or what the unit found wrong in the request.
        if (!entry.reason.isEmpty())
            text += QStringLiteral(" (%1)").arg(entry.reason);
        break;
    }
    case V::NoAnswer: text = QStringLiteral("no answer (%1)").arg(entry.reason); break;
    case V::UnknownUnit: text = QStringLiteral("unknown unit: %1").arg(entry.reason); break;
    case V::ChecksumError:
    case V::Malformed: text = QStringLiteral("malformed: %1").arg(entry.reason); break;
    case V::Garbage: text = QStringLiteral("garbage: %1").arg(entry.reason); break;
    case V::ConnectionOpened: text = QStringLiteral("connection opened"); break;
    case V::ConnectionRefused:
        // "connection refused by maxClients: 2 client(s) connected already, maxClients is 2"
        text = entry.reason.startsWith(QLatin1String("refused "))
                   ? QStringLiteral("connection %1").arg(entry.reason)
                   : QStringLiteral("connection refused: %1").arg(entry.reason);
        break;
    case V::ConnectionClosed: text = QStringLiteral("connection closed (%1)").arg(entry.reason); break;
    }
    if (!faults.isEmpty())
        text += QStringLiteral(", changed by fault (%1)").arg(faults);
    return text;
}

void SimulateSession::printScriptLine(const QString &who, const QString &text, bool error)
{
    // Errors are said even with --quiet: a script that fails answers differently.
    if (m_options.quiet && !error)
        return;
    const QString line = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss.zzz")) + QStringLiteral("  script ") + who
                         + QStringLiteral("  ") + (error ? QStringLiteral("error: ") : QStringLiteral("log: ")) + text;
    // What a script's top level logs while loading comes after the "simulating" header.
    if (!m_started) {
        m_heldLines.append(line);
        return;
    }
    m_out << line << Qt::endl;
}

void SimulateSession::printLine(const SimLogEntry &entry, const FaultPlan *plan)
{
    const QString time = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss.zzz"));
    QString what;
    if (isRequest(entry.verdict) && !entry.request.isEmpty() && m_delimited.contains(entry.endpoint)) {
        // A delimited protocol's frames are shown as they are, the answer after an arrow.
        what = DelimitedFramer::toText(entry.request);
        if (!entry.response.isEmpty())
            what += QStringLiteral(" -> ") + DelimitedFramer::toText(entry.response);
    } else if (isRequest(entry.verdict) && !entry.request.isEmpty()) {
        const AduParts request = AduBuilder::parse(entry.request, framingOf(entry.endpoint));
        if (!request.pdu.isEmpty()) {
            const quint8 function = quint8(request.pdu.at(0));
            what = QStringLiteral("%1 %2").arg(hexNumber(function, 2)).arg(QLatin1String(functionName(function)));
        }
    }
    m_out << time << "  " << entry.endpoint << "  " << entry.peer;
    if (entry.unitId >= 0)
        m_out << "  unit " << entry.unitId;
    if (!what.isEmpty())
        m_out << "  " << what;
    m_out << "  " << verdictText(entry, plan) << Qt::endl;
}

} // namespace mbscope::app
