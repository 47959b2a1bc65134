#include "seriallink.h"

#include "monotonicclock.h"
#include "protocol/rtuframer.h"
#include "rtsdirection.h"
#include "seriallinecontrol.h"

#include <QtCore/QFile>

#include <cerrno>
#include <grp.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace mbscope {

namespace {

LinkError::Kind kindForErrno(int osError)
{
    switch (osError) {
    case ENOENT:
    case ENODEV:
    case ENXIO: return LinkError::Kind::NotFound;
    case EACCES:
    case EPERM: return LinkError::Kind::Permission;
    default: return LinkError::Kind::Io;
    }
}

QString describeSettings(const SerialSettings &s)
{
    return QStringLiteral("%1 baud, %2%3%4").arg(s.baud).arg(s.dataBits).arg(QLatin1Char(s.parity)).arg(s.stopBits);
}

} // namespace

SerialLink::SerialLink(const LinkUrl &url, QObject *parent)
    : Link(url, parent)
    , m_drainTimer(this) // a child, so that moveToThread() takes it along
{
    m_drainTimer.setSingleShot(true);
    m_drainTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_drainTimer, &QTimer::timeout, this, &SerialLink::onDrainTimer);
    if (url.serial.rs485.enabled()) {
        m_rts = new RtsDirection(url.serial.rs485, url.serial.device, [this](const QByteArray &bytes) { return writeNow(bytes); },
                                 this);
        connect(m_rts, &RtsDirection::failed, this, [this](const QString &what) { reportError(LinkError::Kind::Io, what); });
    }
}

SerialLink::~SerialLink()
{
    teardown();
}

qint64 SerialLink::t15Ns() const
{
    return RtuFramer::t15Ns(url().serial.baud);
}

qint64 SerialLink::t35Ns() const
{
    return RtuFramer::t35Ns(url().serial.baud);
}

qint64 SerialLink::lineCharacterNs(const SerialSettings &s)
{
    if (s.baud <= 0)
        return 0;
    const int bits = 1 + s.dataBits + (s.parity == 'N' ? 0 : 1) + s.stopBits;
    return qint64(bits) * 1000000000LL / s.baud;
}

QString SerialLink::owningGroup(const QString &path)
{
    struct stat info {};
    if (::stat(QFile::encodeName(path).constData(), &info) != 0)
        return {};
    std::vector<char> buffer(16384);
    group entry {};
    group *found = nullptr;
    if (::getgrgid_r(info.st_gid, &entry, buffer.data(), buffer.size(), &found) != 0 || !found)
        return {};
    return QString::fromLocal8Bit(found->gr_name);
}

QString SerialLink::openFailureMessage(const QString &device, int osError)
{
    switch (osError) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
        return QStringLiteral("no such device %1 (%2): is the adapter plugged in? "
                              "'ls /dev/serial/by-id' lists the serial devices present")
            .arg(device, qt_error_string(osError));
    case EACCES:
    case EPERM: {
        const QString group = owningGroup(device);
        if (group.isEmpty())
            return QStringLiteral("permission denied opening %1 (%2): ask for read and write access to it")
                .arg(device, qt_error_string(osError));
        return QStringLiteral("permission denied opening %1 (%2): it belongs to group '%3'; join that group with "
                              "'sudo usermod -aG %3 $USER', then log out and in again")
            .arg(device, qt_error_string(osError), group);
    }
    case EBUSY:
        return QStringLiteral("%1 is in use by another program (%2)").arg(device, qt_error_string(osError));
    case ENOTTY:
        return QStringLiteral("%1 is not a serial port (not a terminal device)").arg(device);
    default:
        return QStringLiteral("cannot open %1 (%2)").arg(device, qt_error_string(osError));
    }
}

void SerialLink::open()
{
    if (state() != State::Closed)
        return;
    setState(State::Opening);
    // A port opens at once, but the outcome is signalled after open() returns, as on every link.
    QMetaObject::invokeMethod(this, &SerialLink::startOpen, Qt::QueuedConnection);
}

void SerialLink::startOpen()
{
    if (state() != State::Opening || m_port)
        return;
    const SerialSettings &s = url().serial;
    auto failWith = [this](LinkError::Kind kind, const QString &what) {
        teardown();
        setState(State::Closed);
        reportError(kind, what);
    };
    // Ask the file system first: QSerialPort's errors lose errno, and the message should say
    // whether the device is missing or forbidden (and which group may use it).
    const QByteArray path = QFile::encodeName(s.device);
    struct stat info {};
    // Listen-only: read access is all the port needs, and the port is opened for reading only, so
    // no byte can leave through it.
    const int access = isListenOnly() ? R_OK : R_OK | W_OK;
    if (::stat(path.constData(), &info) != 0 || ::access(path.constData(), access) != 0) {
        const int osError = errno;
        failWith(kindForErrno(osError), openFailureMessage(s.device, osError));
        return;
    }
    if (!S_ISCHR(info.st_mode)) {
        failWith(LinkError::Kind::Config, openFailureMessage(s.device, ENOTTY));
        return;
    }

    m_port = new QSerialPort(this);
    m_port->setPortName(s.device);
    m_port->setBaudRate(s.baud);
    m_port->setDataBits(QSerialPort::DataBits(s.dataBits));
    m_port->setParity(s.parity == 'E' ? QSerialPort::EvenParity
                      : s.parity == 'O' ? QSerialPort::OddParity
                                        : QSerialPort::NoParity);
    m_port->setStopBits(s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port->open(isListenOnly() ? QIODevice::ReadOnly : QIODevice::ReadWrite)) {
        const QSerialPort::SerialPortError error = m_port->error();
        const QString os = osAnswer(m_port->errorString());
        switch (error) {
        case QSerialPort::DeviceNotFoundError:
            failWith(LinkError::Kind::NotFound, openFailureMessage(s.device, ENOENT));
            break;
        case QSerialPort::PermissionError:
            // access() allowed it, so this is QSerialPort's lock: another program has the port.
            failWith(LinkError::Kind::Io, QStringLiteral("%1 is in use by another program (%2)").arg(s.device, os));
            break;
        case QSerialPort::UnsupportedOperationError:
            failWith(LinkError::Kind::Config,
                     QStringLiteral("%1 cannot be set to %2 (%3)").arg(s.device, describeSettings(s), os));
            break;
        default:
            failWith(LinkError::Kind::Io, QStringLiteral("cannot open %1 (%2)").arg(s.device, os));
            break;
        }
        return;
    }
    if (m_rts) {
        const int fd = int(m_port->handle());
        std::unique_ptr<LineControl> lines;
        if (m_lineControlFactory)
            lines = m_lineControlFactory(fd);
        else
            lines = std::make_unique<SerialLineControl>(fd);
        const QString why = m_rts->start(std::move(lines));
        if (!why.isEmpty()) {
            failWith(LinkError::Kind::Config, why);
            return;
        }
    }
    connect(m_port, &QIODevice::readyRead, this, &SerialLink::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialLink::onPortError);
    connect(m_port, &QIODevice::bytesWritten, this, [this] {
        if (!m_inWrite)
            account();
    });
    m_submitted = 0;
    m_accepted = 0;
    m_lineFreeNs = 0;
    m_readErrors = 0;
    setState(State::Open);
    Q_EMIT opened();
}

void SerialLink::close()
{
    if (state() == State::Closed)
        return;
    teardown();
    setClosed(QStringLiteral("closed on request"));
}

void SerialLink::teardown()
{
    m_drainTimer.stop();
    m_marks.clear();
    m_drains.clear();
    if (!m_port)
        return;
    if (m_rts)
        m_rts->stop(); // while the port is open: RTS back to rest, the driver's settings back
    QSerialPort *port = m_port;
    m_port = nullptr;
    disconnect(port, nullptr, this, nullptr);
    port->close();
    port->deleteLater();
}

bool SerialLink::write(const QByteArray &bytes)
{
    if (refuseWriteWhenListening(bytes.size()))
        return false;
    if (state() != State::Open || !m_port) {
        reportError(LinkError::Kind::Closed,
                    QStringLiteral("cannot write %1 bytes: the link is not open").arg(bytes.size()));
        return false;
    }
    return m_rts ? m_rts->send(bytes) : writeNow(bytes);
}

bool SerialLink::writeNow(const QByteArray &bytes)
{
    if (!m_port)
        return false;
    const qint64 written = m_port->write(bytes);
    if (written != bytes.size()) {
        reportError(LinkError::Kind::Io, QStringLiteral("writing %1 bytes to %2 failed (%3)")
                                             .arg(bytes.size())
                                             .arg(url().serial.device, osAnswer(m_port->errorString())));
        return false;
    }
    m_submitted += written;
    m_marks.append(m_submitted);
    // Hand the bytes to the kernel now, not at the next turn of the event loop.
    m_inWrite = true;
    m_port->flush();
    m_inWrite = false;
    if (!m_port)
        return false;
    account();
    return true;
}

void SerialLink::account()
{
    if (!m_port)
        return;
    const qint64 accepted = m_submitted - m_port->bytesToWrite();
    if (accepted < m_accepted || (accepted == m_accepted && (m_marks.isEmpty() || m_marks.first() > accepted)))
        return;
    const qint64 now = monotonicNowNs();
    const qint64 start = qMax(now, m_lineFreeNs);
    const qint64 character = lineCharacterNs(url().serial);
    while (!m_marks.isEmpty() && m_marks.first() <= accepted) {
        m_drains.append(start + (m_marks.first() - m_accepted) * character);
        m_marks.removeFirst();
    }
    m_lineFreeNs = start + (accepted - m_accepted) * character;
    m_accepted = accepted;
    if (m_rts && m_marks.isEmpty())
        m_rts->drained(m_lineFreeNs); // all taken: RTS back rts_after after the last byte
    scheduleDrain();
}

void SerialLink::scheduleDrain()
{
    if (m_drains.isEmpty() || m_drainTimer.isActive())
        return;
    const qint64 wait = m_drains.first() - monotonicNowNs();
    m_drainTimer.start(int(qMax<qint64>(0, (wait + 999999) / 1000000)));
}

void SerialLink::onDrainTimer()
{
    const qint64 now = monotonicNowNs();
    while (!m_drains.isEmpty() && m_drains.first() <= now) {
        const qint64 drained = m_drains.takeFirst();
        deliverWritten(drained);
        if (!m_port)
            return;
    }
    scheduleDrain();
}

void SerialLink::onReadyRead()
{
    if (!m_port)
        return;
    const qint64 now = monotonicNowNs();
    const QByteArray bytes = m_port->readAll();
    if (!bytes.isEmpty()) {
        m_readErrors = 0;
        deliverReceived(bytes, now, now);
    }
}

bool SerialLink::hungUp() const
{
    if (!m_port || m_port->handle() < 0)
        return false;
    pollfd probe{int(m_port->handle()), POLLIN, 0};
    return ::poll(&probe, 1, 0) == 1 && (probe.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

void SerialLink::onPortError(QSerialPort::SerialPortError error)
{
    if (!m_port || error == QSerialPort::NoError || error == QSerialPort::TimeoutError)
        return;
    const QString os = osAnswer(m_port->errorString());
    const QString device = url().serial.device;
    // A device that went away (unplugged adapter, pty whose other end closed) reads as end of
    // file or EIO with a hang-up on the descriptor: QSerialPort reports a ResourceError, or a
    // ReadError over and over while the descriptor stays readable. Either way the link is lost.
    if (error == QSerialPort::ResourceError || (error == QSerialPort::ReadError && (hungUp() || ++m_readErrors >= 100))) {
        if (m_port->bytesAvailable() > 0)
            onReadyRead();
        if (!m_port)
            return;
        // After a hang-up, read() returned 0 and errno is stale: say what the descriptor said.
        const QString why = error == QSerialPort::ResourceError ? os : QStringLiteral("the line hung up");
        teardown();
        reportLoss(LinkError::Kind::Closed, QStringLiteral("%1 went away (unplugged?): %2").arg(device, why));
        return;
    }
    const char *what = error == QSerialPort::WriteError ? "writing to" : error == QSerialPort::ReadError ? "reading from" : "using";
    m_port->clearError();
    reportError(LinkError::Kind::Io, QStringLiteral("%1 %2 failed (%3)").arg(QLatin1String(what), device, os));
}

} // namespace mbscope

#include "moc_seriallink.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
