#include "watchcsvlog.h"

#include "watch/watchblock.h"
#include "watch/watchdecoder.h"

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>

namespace mbscope {

namespace {

QString hex4(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

QString isoTime(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

} // namespace

WatchCsvLog::WatchCsvLog(const WatchLogSettings &settings, const QString &baseDirectory)
    : m_settings(settings)
{
    m_directory = QDir::isAbsolutePath(settings.directory) || baseDirectory.isEmpty()
        ? QDir::cleanPath(settings.directory)
        : QDir::cleanPath(QDir(baseDirectory).absoluteFilePath(settings.directory));
}

WatchCsvLog::~WatchCsvLog()
{
    close();
}

QString WatchCsvLog::csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n'))
        && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QString WatchCsvLog::fileStem(const QString &name)
{
    QString stem;
    for (const QChar c : name)
        stem += (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('.')) ? c : QLatin1Char('_');
    return stem.isEmpty() ? QStringLiteral("watch") : stem;
}

QString WatchCsvLog::header(const WatchDefinition &watch)
{
    // The columns are the values a full answer decodes into (a FIFO: its most values).
    const int words = watch.quantity * WatchBlock::wordsPerAddress(watch);
    const QList<WatchPointValue> layout = WatchDecoder::decode(watch, QList<quint16>(words, 0), QList<bool>(watch.quantity, false));
    QStringList columns{QStringLiteral("time"), QStringLiteral("status")};
    for (const WatchPointValue &v : layout) {
        QString column = v.name.isEmpty() ? hex4(v.address) : v.name;
        if (!v.unit.isEmpty())
            column += QStringLiteral(" [%1]").arg(v.unit);
        columns.append(csvField(column));
    }
    columns.append(QStringLiteral("error"));
    return columns.join(QLatin1Char(','));
}

bool WatchCsvLog::open(const QList<WatchDefinition> &watches, QString *error)
{
    close();
    if (!QDir().mkpath(m_directory)) {
        if (error)
            *error = QStringLiteral("%1: the log directory cannot be made").arg(m_directory);
        return false;
    }
    m_logs.clear();
    for (const WatchDefinition &w : watches) {
        File f;
        f.watch = w;
        m_logs.push_back(std::move(f));
    }
    return true;
}

bool WatchCsvLog::startFile(File &f, qint64 timeMs, QString *error)
{
    if (f.file)
        f.file->close();
    const QString stamp = QDateTime::fromMSecsSinceEpoch(timeMs, Qt::UTC).toString(QStringLiteral("yyyyMMdd-HHmmss"));
    const QString stem = QDir(m_directory).filePath(fileStem(f.watch.name) + QLatin1Char('-') + stamp);
    QString path = stem + QStringLiteral(".csv");
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = stem + QStringLiteral("-%1.csv").arg(n);
    f.file = std::make_unique<QFile>(path);
    if (!f.file->open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = QStringLiteral("%1: cannot be written: %2").arg(path, f.file->errorString());
        f.file.reset();
        return false;
    }
    const QByteArray head = (header(f.watch) + QLatin1Char('\n')).toUtf8();
    f.file->write(head);
    f.bytes = head.size();
    f.startedMs = timeMs;
    f.hasRow = false;
    m_files.append(path);
    return true;
}

bool WatchCsvLog::append(int watch, qint64 timeMs, const QString &status, const QList<WatchPointValue> &values,
                         const QString &errorText, QString *error)
{
    if (watch < 0 || watch >= int(m_logs.size()))
        return true;
    File &f = m_logs[std::size_t(watch)];
    QStringList texts;
    texts.reserve(values.size());
    for (const WatchPointValue &v : values)
        texts.append(v.text);
    if (m_settings.mode == WatchLogSettings::Mode::OnChange && f.hasRow && status == f.lastStatus
        && (texts == f.lastValues || texts.isEmpty()))
        return true;
    const bool roll = f.file
        && ((m_settings.rollBytes > 0 && f.bytes >= m_settings.rollBytes)
            || (m_settings.rollSeconds > 0 && timeMs - f.startedMs >= m_settings.rollSeconds * 1000));
    if (!f.file || roll) {
        if (!startFile(f, timeMs, error))
            return false;
    }
    QStringList row{isoTime(timeMs), status};
    for (const QString &t : std::as_const(texts))
        row.append(csvField(t));
    if (texts.isEmpty()) {
        // A failed poll: the value columns are left empty.
        const int columns = int(header(f.watch).count(QLatin1Char(','))) - 2;
        for (int i = 0; i < columns; ++i)
            row.append(QString());
    }
    row.append(csvField(errorText));
    const QByteArray line = (row.join(QLatin1Char(',')) + QLatin1Char('\n')).toUtf8();
    if (f.file->write(line) != line.size()) {
        if (error)
            *error = QStringLiteral("%1: cannot be written: %2").arg(f.file->fileName(), f.file->errorString());
        return false;
    }
    f.bytes += line.size();
    f.hasRow = true;
    f.lastStatus = status;
    if (!texts.isEmpty())
        f.lastValues = texts;
    if (timeMs - m_lastFlushMs >= 1000) {
        flush();
        m_lastFlushMs = timeMs;
    }
    return true;
}

void WatchCsvLog::flush()
{
    for (File &f : m_logs) {
        if (f.file)
            f.file->flush();
    }
}

void WatchCsvLog::close()
{
    for (File &f : m_logs) {
        if (f.file) {
            f.file->close();
            f.file.reset();
        }
    }
}

} // namespace mbscope
