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
    if (m_end != ScanEnd::Completed)
        return false;
    if (m_stopRequested)
        m_end = ScanEnd::Stopped;
    else if (m_clock.elapsed() + timeoutMs > m_settings.maxDurationMs)
        m_end = ScanEnd::TimeLimit;
    return m_end == ScanEnd::Completed;
}

bool LineScanner::pass(const QList<quint8> &ids, QList<LineTrial> &out, int total)
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
                // The request and its answer on the line at 11 bits a character (Serial Line V1.02,
                // 2.5.1): 8 bytes out, 5 + the data back, ASCII twice as many characters and more.
                const int data = m_settings.function <= 2 ? (m_settings.quantity + 7) / 8 : 2 * m_settings.quantity;
                const int characters = (8 + 5 + data) * (url.framing() == Framing::Ascii ? 3 : 1);
                const int timeoutMs = m_settings.timeoutMs + int(characters * 11 * 1000LL / baud);
                for (const quint8 unit : ids) {
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
                    ++m_done;
                    Q_EMIT tried(trial);
                    ScanProgress p;
                    p.done = m_done;
                    p.total = total;
                    p.elapsedMs = m_clock.elapsed();
                    p.remainingMs = qMin(p.elapsedMs * qMax(0, total - m_done) / qMax(1, m_done),
                                         qMax<qint64>(0, m_settings.maxDurationMs - p.elapsedMs));
                    for (const LineTrial &t : std::as_const(out))
                        p.found += t.works() ? 1 : 0;
                    Q_EMIT progressChanged(p);
                    if (trial.probe.kind == UnitProbeKind::LinkError) {
                        m_end = ScanEnd::LinkError;
                        return false;
                    }
                    if (trial.works()) {
                        if (m_settings.stopAtFirst)
                            return false;
                        break; // the next setting: this one is known to work
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
    m_end = ScanEnd::Completed;
    m_done = 0;
    m_clock.start();
    QList<LineTrial> trials;
    const int combos = int(settings.bauds.size() * settings.parities.size() * settings.stopBits.size());
    if (!settings.units.isEmpty()) {
        pass(settings.units, trials, combos * int(settings.units.size()));
    } else if (pass({1}, trials, combos)) {
        bool any = false;
        for (const LineTrial &t : std::as_const(trials))
            any = any || t.works();
        if (!any) {
            QList<quint8> rest;
            for (int u = 2; u <= 247; ++u)
                rest.append(quint8(u));
            pass(rest, trials, combos * 247);
        }
    }
    m_channel->closeLink();
    return trials;
}

} // namespace mbscope
