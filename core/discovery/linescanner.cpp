#include "linescanner.h"

#include "unitclassifier.h"
#include "unitscanner.h"

namespace mbscope {

QString LineScanSettings::problem() const
{
    if (!url.isSerial())
        return QStringLiteral("%1 is no serial port: line settings are scanned on rtu:// and ascii:// links")
            .arg(url.toString());
    if (bauds.isEmpty() || parities.isEmpty() || stopBits.isEmpty())
        return QStringLiteral("no baud rate, parity or stop bits to try");
    for (const int b : bauds) {
        if (b < 50 || b > 4000000)
            return QStringLiteral("baud rate %1 is out of range: expected 50 to 4000000").arg(b);
    }
    for (const char p : parities) {
        if (p != 'N' && p != 'E' && p != 'O')
            return QStringLiteral("parity '%1': expected N, E or O").arg(QLatin1Char(p));
    }
    for (const int s : stopBits) {
        if (s != 1 && s != 2)
            return QStringLiteral("stop bits %1: expected 1 or 2").arg(s);
    }
    for (const quint8 u : units) {
        if (u < 1 || u > 247)
            return QStringLiteral("unit %1: a serial line's ids are 1-247 (0 is the broadcast)").arg(u);
    }
    if (function < 1 || function > 4)
        return QStringLiteral("function %1 is not a read: 01, 02, 03 or 04").arg(function);
    if (timeoutMs < 1 || maxDurationMs < 1)
        return QStringLiteral("the timeout and the time limit must be positive");
    return {};
}

bool LineTrial::works() const
{
    switch (probe.kind) {
    case UnitProbeKind::Answers:
    case UnitProbeKind::Exception:
    case UnitProbeKind::GatewayPathUnavailable:
    case UnitProbeKind::GatewayTargetFailed:
        return true;
    default:
        return false;
    }
}

QString LineTrial::settingText() const
{
    return QStringLiteral("%1 8%2%3").arg(baud).arg(QLatin1Char(parity)).arg(stopBits);
}

LineScanner::LineScanner(QObject *parent)
    : QObject(parent)
    , m_channel(new ProbeChannel(this))
{
}

bool LineScanner::mayContinue(int timeoutMs)
{
    if (m_end != JobEnd::Completed)
        return false;
    if (m_stopRequested)
        m_end = JobEnd::Stopped;
    else if (m_clock.elapsed() + timeoutMs > m_settings.maxDurationMs)
        m_end = JobEnd::TimeLimit;
    return m_end == JobEnd::Completed;
}

int LineScanner::timeoutAt(int baud) const
{
    // The request and its answer on the line at 11 bits a character (Serial Line V1.02, 2.5.1):
    // 8 bytes out, 5 + the data back, ASCII twice as many characters and more.
    const int data = m_settings.function <= 2 ? (m_settings.quantity + 7) / 8 : 2 * m_settings.quantity;
    const int characters = (8 + 5 + data) * (m_settings.url.framing() == Framing::Ascii ? 3 : 1);
    return m_settings.timeoutMs + int(characters * 11 * 1000LL / baud);
}

void LineScanner::skip(int trials, int timeoutMs)
{
    m_done += trials;
    m_plannedLeftMs = qMax<qint64>(0, m_plannedLeftMs - qint64(trials) * timeoutMs);
}

JobProgress LineScanner::progress() const
{
    JobProgress p;
    p.total = m_total;
    p.done = qMin(m_done, m_total);
    p.found = m_found;
    p.elapsedMs = m_clock.isValid() ? m_clock.elapsed() : 0;
    // Before the first trial every one is taken to wait its whole timeout (a wrong setting is
    // silent); then the timeouts left are scaled by what the trials so far took of theirs.
    const double ratio = m_plannedRunMs > 0 ? double(p.elapsedMs) / double(m_plannedRunMs) : 1.0;
    p.remainingMs = qMin(qint64(double(m_plannedLeftMs) * ratio), qMax<qint64>(0, m_settings.maxDurationMs - p.elapsedMs));
    return p;
}

bool LineScanner::pass(const QList<quint8> &ids, QList<LineTrial> &out)
{
    const QByteArray pdu = UnitScanner::readPdu(m_settings.function, m_settings.address, m_settings.quantity);
    for (const int baud : m_settings.bauds) {
        for (const char parity : m_settings.parities) {
            for (const int stop : m_settings.stopBits) {
                LinkUrl url = m_settings.url;
                url.serial.baud = baud;
                url.serial.parity = parity;
                url.serial.stopBits = stop;
                m_channel->setTarget(url);
                const int timeoutMs = timeoutAt(baud);
                for (qsizetype i = 0; i < ids.size(); ++i) {
                    const quint8 unit = ids.at(i);
                    if (!mayContinue(timeoutMs))
                        return false;
                    const std::optional<ProbeChannel::Answer> answer = m_channel->ask(unit, pdu, timeoutMs);
                    if (!answer)
                        return false;
                    LineTrial trial;
                    trial.baud = baud;
                    trial.parity = parity;
                    trial.stopBits = stop;
                    trial.unit = unit;
                    trial.probe = UnitClassifier::classify(unit, answer->transaction, url.framing(), answer->bytesRead);
                    out.append(trial);
                    m_found += trial.works() ? 1 : 0;
                    m_plannedRunMs += timeoutMs;
                    skip(1, timeoutMs);
                    Q_EMIT tried(trial);
                    if (trial.works() && !m_settings.stopAtFirst)
                        skip(int(ids.size() - i - 1), timeoutMs); // the next setting: this one is known to work
                    Q_EMIT progressChanged(progress());
                    if (trial.probe.kind == UnitProbeKind::LinkError) {
                        m_end = JobEnd::LinkError;
                        return false;
                    }
                    if (trial.works()) {
                        if (m_settings.stopAtFirst)
                            return false;
                        break;
                    }
                }
            }
        }
    }
    return true;
}

std::optional<QList<LineTrial>> LineScanner::run(const LineScanSettings &settings)
{
    if (!settings.problem().isEmpty())
        return std::nullopt;
    m_settings = settings;
    m_stopRequested = false;
    m_end = JobEnd::Completed;
    m_done = 0;
    m_found = 0;
    m_plannedRunMs = 0;
    // The plan: every setting with every id given; without ids, 1 on every setting and then, in
    // case nothing answers, 2-247 on every setting.
    const qsizetype idsPerSetting = settings.units.isEmpty() ? 247 : settings.units.size();
    qint64 perRound = 0;
    for (const int baud : settings.bauds)
        perRound += qint64(timeoutAt(baud)) * settings.parities.size() * settings.stopBits.size();
    const int combos = int(settings.bauds.size() * settings.parities.size() * settings.stopBits.size());
    m_total = combos * int(idsPerSetting);
    m_plannedLeftMs = perRound * idsPerSetting;
    m_clock.start();
    Q_EMIT progressChanged(progress());
    QList<LineTrial> trials;
    if (!settings.units.isEmpty()) {
        pass(settings.units, trials);
    } else if (pass({1}, trials) && m_found == 0) {
        QList<quint8> rest;
        for (int u = 2; u <= 247; ++u)
            rest.append(quint8(u));
        pass(rest, trials);
    }
    m_channel->closeLink();
    // Completed: what was not asked was not needed (a setting answered, or --first).
    if (m_end == JobEnd::Completed)
        skip(m_total - m_done, 0);
    JobProgress last = progress();
    last.remainingMs = 0;
    Q_EMIT progressChanged(last);
    return trials;
}

} // namespace mbscope

#include "moc_linescanner.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
