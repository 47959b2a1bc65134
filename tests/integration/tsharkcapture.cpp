#include "tsharkcapture.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFileInfo>
#include <QtCore/QStandardPaths>
#include <QtCore/QThread>

namespace mbscope::testpeers {

namespace {

// "1795274544.034088874" to nanoseconds without going through a double (19 digits do not fit
// in one).
bool parseEpochNs(const QByteArray &text, qint64 *ns)
{
    const int dot = int(text.indexOf('.'));
    bool ok = false;
    const qint64 seconds = (dot < 0 ? text : text.left(dot)).toLongLong(&ok);
    if (!ok)
        return false;
    qint64 fraction = 0;
    if (dot >= 0) {
        const QByteArray digits = text.mid(dot + 1).left(9).leftJustified(9, '0');
        fraction = digits.toLongLong(&ok);
        if (!ok)
            return false;
    }
    *ns = seconds * 1000000000LL + fraction;
    return true;
}

} // namespace

TsharkCapture::~TsharkCapture()
{
    if (m_tshark && m_tshark->state() != QProcess::NotRunning) {
        m_tshark->kill();
        m_tshark->waitForFinished(5000);
    }
}

bool TsharkCapture::start(quint16 port, int timeoutMs)
{
    if (QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty()) {
        m_error = QStringLiteral("tshark is not installed (Debian: apt-get install tshark)");
        return false;
    }
    m_dir = std::make_unique<QTemporaryDir>();
    if (!m_dir->isValid()) {
        m_error = QStringLiteral("no temporary directory: ") + m_dir->errorString();
        return false;
    }
    m_port = port;
    m_file = m_dir->filePath(QStringLiteral("loopback.pcapng"));
    m_tshark = std::make_unique<QProcess>();
    m_tshark->setReadChannel(QProcess::StandardError); // "Capturing on 'Loopback: lo'" comes on stderr
    m_tshark->start(QStringLiteral("tshark"),
                    {QStringLiteral("-i"), QStringLiteral("lo"), QStringLiteral("-f"),
                     QStringLiteral("tcp port ") + QString::number(port), QStringLiteral("-w"), m_file});
    QDeadlineTimer deadline(timeoutMs);
    QByteArray log;
    // "Capturing on 'Loopback: lo'" comes when tshark has started dumpcap, "Capture started."
    // once dumpcap has the interface open with its filter: packets before that are not captured.
    while (!log.contains("Capture started")) {
        if (m_tshark->state() == QProcess::NotRunning || deadline.hasExpired()) {
            log += m_tshark->readAllStandardError();
            m_error = QStringLiteral("tshark cannot capture on lo (capturing needs root or the wireshark "
                                     "group; a container may have no lo): ") + QString::fromLocal8Bit(log).trimmed();
            return false;
        }
        m_tshark->waitForReadyRead(100);
        log += m_tshark->readAllStandardError();
    }
    return true;
}

bool TsharkCapture::stopAndRead(QList<WireSegment> *segments, int timeoutMs)
{
    if (!m_tshark) {
        m_error = QStringLiteral("no capture was started");
        return false;
    }
    // dumpcap (behind tshark) writes with stdio buffering and may still be reading the capture
    // buffer: wait until the file has stopped growing before stopping it, or the last packets are
    // lost with the buffers.
    QDeadlineTimer settle(timeoutMs / 2);
    qint64 size = -1;
    int quiet = 0;
    while (quiet < 5 && !settle.hasExpired()) {
        QThread::msleep(200);
        const qint64 now = QFileInfo(m_file).size();
        quiet = now == size ? quiet + 1 : 0;
        size = now;
    }
    m_tshark->terminate();
    if (!m_tshark->waitForFinished(timeoutMs)) {
        m_error = QStringLiteral("tshark did not stop on SIGTERM");
        return false;
    }
    if (!QFileInfo::exists(m_file)) {
        m_error = QStringLiteral("tshark wrote no capture file: ") + QString::fromLocal8Bit(m_tshark->readAllStandardError());
        return false;
    }

    QProcess reader;
    reader.start(QStringLiteral("tshark"),
                 {QStringLiteral("-r"), m_file, QStringLiteral("-Y"), QStringLiteral("tcp.len > 0"),
                  QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"), QStringLiteral("frame.time_epoch"),
                  QStringLiteral("-e"), QStringLiteral("tcp.srcport"), QStringLiteral("-e"), QStringLiteral("tcp.dstport"),
                  QStringLiteral("-e"), QStringLiteral("tcp.payload")});
    if (!reader.waitForFinished(timeoutMs) || reader.exitStatus() != QProcess::NormalExit || reader.exitCode() != 0) {
        m_error = QStringLiteral("tshark -r failed: ") + QString::fromLocal8Bit(reader.readAllStandardError());
        return false;
    }
    segments->clear();
    const QList<QByteArray> lines = reader.readAllStandardOutput().split('\n');
    for (const QByteArray &line : lines) {
        const QList<QByteArray> columns = line.trimmed().split('\t');
        if (columns.size() < 4)
            continue;
        WireSegment s;
        if (!parseEpochNs(columns.at(0), &s.timeNs)) {
            m_error = QStringLiteral("unreadable capture time: ") + QString::fromLatin1(columns.at(0));
            return false;
        }
        s.sourcePort = quint16(columns.at(1).toUInt());
        s.destinationPort = quint16(columns.at(2).toUInt());
        s.payload = QByteArray::fromHex(columns.at(3)); // fromHex skips separators
        segments->append(s);
    }
    return true;
}

} // namespace mbscope::testpeers
