#include "rtsdirection.h"

#include "monotonicclock.h"

#include <cerrno>
#include <utility>

namespace mbscope {

namespace {

constexpr qint64 kNsPerUs = 1000;

QString levelName(bool up)
{
    return up ? QStringLiteral("up") : QStringLiteral("down");
}

QString describe(const KernelRs485 &k)
{
    if (!k.enabled)
        return QStringLiteral("RS-485 mode off");
    return QStringLiteral("RTS %1 while sending and %2 after, %3 ms before, %4 ms after")
        .arg(levelName(k.rtsOnSend), levelName(k.rtsAfterSend))
        .arg(k.delayBeforeMs)
        .arg(k.delayAfterMs);
}

// The errors that mean "this port or driver cannot do that", not "it failed this time".
bool unsupported(int osError)
{
    return osError == ENOTTY || osError == EINVAL || osError == ENOTSUP || osError == ENOSYS;
}

} // namespace

RtsDirection::RtsDirection(const Rs485Settings &settings, const QString &device, Writer writer, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_device(device)
    , m_writer(std::move(writer))
    , m_clock(&monotonicNowNs)
    , m_timer(this) // a child, so that moveToThread() takes it along
{
    connect(&m_timer, &DueTimer::timeout, this, &RtsDirection::service);
}

qint64 RtsDirection::now() const
{
    return m_clock();
}

QString RtsDirection::start(std::unique_ptr<LineControl> lines)
{
    stop();
    m_lines = std::move(lines);
    if (m_settings.kernel)
        return startKernel();
    const QString option = QStringLiteral("rts=") + levelName(m_settings.sendLevel());
    if (const int osError = m_lines->setRts(!m_settings.sendLevel()); osError != 0) {
        m_lines.reset();
        const QString what = QStringLiteral("cannot switch RTS on %1 for %2 (%3)").arg(m_device, option, qt_error_string(osError));
        if (!unsupported(osError))
            return what;
        return what + QStringLiteral(": the port has no modem control lines (a pseudo terminal has none); use a port whose "
                                     "RTS drives the transceiver, or leave rts= out if the adapter switches direction by itself");
    }
    m_sending = false;
    return {};
}

QString RtsDirection::startKernel()
{
    KernelRs485 saved;
    m_haveSaved = m_lines->kernelRs485(&saved) == 0;
    m_saved = saved;
    const bool up = m_settings.sendLevel();
    const KernelRs485 wanted{true, up, !up, int(m_settings.beforeUs / 1000), int(m_settings.afterUs / 1000)};
    if (const int osError = m_lines->setKernelRs485(wanted); osError != 0) {
        m_lines.reset();
        if (unsupported(osError))
            return QStringLiteral("%1 has no RS-485 mode for rs485=kernel (TIOCSRS485: %2): its driver does not offer one; "
                                  "leave rs485=kernel out to have mbscope switch RTS itself (rts=%3)")
                .arg(m_device, qt_error_string(osError), levelName(up));
        return QStringLiteral("cannot switch %1 to its driver's RS-485 mode for rs485=kernel (TIOCSRS485: %2)")
            .arg(m_device, qt_error_string(osError));
    }
    m_kernelSet = true;
    // A driver may take the call and change what it cannot do (a delay, the level): say so
    // rather than run with other settings than the URL's.
    KernelRs485 got;
    if (m_lines->kernelRs485(&got) == 0 && got != wanted) {
        stop();
        return QStringLiteral("the driver of %1 does not keep the RS-485 settings of rs485=kernel: asked for %2, it set %3")
            .arg(m_device, describe(wanted), describe(got));
    }
    return {};
}

void RtsDirection::stop()
{
    m_timer.stop();
    m_held.clear();
    m_sendAtNs = 0;
    m_restAtNs = 0;
    if (m_lines) {
        if (m_kernelSet)
            m_lines->setKernelRs485(m_haveSaved ? m_saved : KernelRs485{}); // the port is closing: errors go unsaid
        else if (m_sending)
            m_lines->setRts(!m_settings.sendLevel());
    }
    m_kernelSet = false;
    m_sending = false;
    m_lines.reset();
}

bool RtsDirection::switchRts(bool sending, const char *when)
{
    if (const int osError = m_lines->setRts(sending ? m_settings.sendLevel() : !m_settings.sendLevel()); osError != 0) {
        Q_EMIT failed(QStringLiteral("cannot switch RTS on %1 %2 a send (%3)").arg(m_device, QLatin1String(when), qt_error_string(osError)));
        return false;
    }
    m_sending = sending;
    return true;
}

bool RtsDirection::send(const QByteArray &bytes)
{
    if (!m_lines || m_kernelSet)
        return m_writer(bytes);
    const qint64 t = now();
    m_restAtNs = 0; // a send keeps RTS where it is
    if (!m_sending) {
        if (!switchRts(true, "before"))
            return false;
        if (m_settings.beforeUs > 0) {
            m_sendAtNs = t + qint64(m_settings.beforeUs) * kNsPerUs;
            m_held.append(bytes);
            arm();
            return true;
        }
    }
    if (!m_held.isEmpty()) { // behind the sends that wait for rts_before
        m_held.append(bytes);
        return true;
    }
    const bool ok = writeNow(bytes);
    arm();
    return ok;
}

bool RtsDirection::writeNow(const QByteArray &bytes)
{
    if (m_writer(bytes))
        return true;
    // Nothing (or not all) left: put RTS back after rts_after, from now.
    if (m_lines && m_held.isEmpty() && m_sending && m_restAtNs == 0)
        m_restAtNs = now() + qint64(m_settings.afterUs) * kNsPerUs;
    return false;
}

void RtsDirection::drained(qint64 lineFreeNs)
{
    if (!m_lines || m_kernelSet || !m_sending || !m_held.isEmpty())
        return;
    m_restAtNs = lineFreeNs + qint64(m_settings.afterUs) * kNsPerUs;
    arm();
}

qint64 RtsDirection::deadlineNs() const
{
    if (!m_held.isEmpty())
        return m_sendAtNs;
    return m_restAtNs;
}

void RtsDirection::service()
{
    if (!m_lines)
        return;
    const qint64 t = now();
    if (!m_held.isEmpty() && t >= m_sendAtNs) {
        const QList<QByteArray> held = std::exchange(m_held, {});
        m_sendAtNs = 0;
        for (const QByteArray &bytes : held) {
            if (!writeNow(bytes) || !m_lines) // a failed write drops the rest; the writer may have closed the port
                break;
        }
        if (!m_lines)
            return;
    }
    if (m_held.isEmpty() && m_restAtNs != 0 && now() >= m_restAtNs) {
        m_restAtNs = 0;
        switchRts(false, "after");
    }
    arm();
}

void RtsDirection::arm()
{
    const qint64 due = deadlineNs();
    if (due == 0 || !m_lines) {
        m_timer.stop();
        return;
    }
    // The due time on this object's clock (a test's own, or the monotonic one), as a moment on
    // the monotonic clock the timer counts on.
    m_timer.start(monotonicNowNs() + qMax<qint64>(0, due - now()));
}

} // namespace mbscope

#include "moc_rtsdirection.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
