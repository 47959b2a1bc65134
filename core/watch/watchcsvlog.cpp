#include "watchcsvlog.h"

#include "watch/watchblock.h"
#include "watch/watchdecoder.h"

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>

#include <utility>

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
    return columns(watch).join(QLatin1Char(','));
}

QStringList WatchCsvLog::columns(const WatchDefinition &watch)
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
    return columns;
}

QString WatchCsvLog::eventHeader()
{
    return QStringLiteral("time,event,severity,rule,point,value,message,fired");
}

bool WatchCsvLog::open(const QList<WatchDefinition> &watches, QString *error)
{
    close();
    m_lostRows = 0;
    if (!QDir().mkpath(m_directory)) {
        if (error)
            *error = QStringLiteral("%1: the log directory cannot be made").arg(m_directory);
        return false;
    }
    m_logs.clear();
    for (const WatchDefinition &w : watches) {
        File f;
        f.watch = w;
        f.valueColumns = columns(w).size() - 3;
        m_logs.push_back(std::move(f));
    }
    return true;
}

bool WatchCsvLog::startFile(Output &out, const QString &stemName, const QString &header, qint64 timeMs, QString *error)
{
    if (out.file) {
        flushOutput(out, error);
        out.file->close();
        out.file.reset();
    }
    // The folder may have been removed while logging (a clean-up script, a user): made again.
    if (!QDir().mkpath(m_directory)) {
        if (error)
            *error = QStringLiteral("%1: the log directory cannot be made").arg(m_directory);
        return false;
    }
    const QString stamp = QDateTime::fromMSecsSinceEpoch(timeMs, Qt::UTC).toString(QStringLiteral("yyyyMMdd-HHmmss"));
    const QString stem = QDir(m_directory).filePath(stemName + QLatin1Char('-') + stamp);
    QString path = stem + QStringLiteral(".csv");
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = stem + QStringLiteral("-%1.csv").arg(n);
    out.file = std::make_unique<QFile>(path);
    if (!out.file->open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = QStringLiteral("%1: cannot be written: %2").arg(path, out.file->errorString());
        out.file.reset();
        return false;
    }
    const QByteArray head = (header + QLatin1Char('\n')).toUtf8();
    out.file->write(head);
    out.bytes = head.size();
    out.startedMs = timeMs;
    out.unflushedRows = 0;
    m_files.append(path);
    return true;
}

bool WatchCsvLog::writeRow(Output &out, const QString &stem, const QString &header, qint64 timeMs, const QByteArray &line,
                           QString *error)
{
    const bool roll = out.file
        && ((m_settings.rollBytes > 0 && out.bytes >= m_settings.rollBytes)
            || (m_settings.rollSeconds > 0 && timeMs - out.startedMs >= m_settings.rollSeconds * 1000));
    if ((!out.file || roll) && !startFile(out, stem, header, timeMs, error)) {
        ++m_lostRows;
        return false;
    }
    if (out.file->write(line) != line.size()) {
        if (error)
            *error = QStringLiteral("%1: cannot be written: %2").arg(out.file->fileName(), out.file->errorString());
        ++m_lostRows;
        return false;
    }
    out.bytes += line.size();
    ++out.unflushedRows;
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
    QStringList row{isoTime(timeMs), status};
    for (const QString &t : std::as_const(texts))
        row.append(csvField(t));
    // A failed poll leaves the value columns empty, and a FIFO that holds fewer values than its
    // most the columns after them: every row has the header's columns.
    for (qsizetype i = texts.size(); i < f.valueColumns; ++i)
        row.append(QString());
    row.append(csvField(errorText));
    const QByteArray line = (row.join(QLatin1Char(',')) + QLatin1Char('\n')).toUtf8();
    if (!writeRow(f.values, fileStem(f.watch.name), header(f.watch), timeMs, line, error))
        return false;
    f.hasRow = true;
    f.lastStatus = status;
    if (!texts.isEmpty())
        f.lastValues = texts;
    return maybeFlush(timeMs, error);
}

bool WatchCsvLog::appendEvent(const WatchRuleEvent &event, QString *error)
{
    if (event.watch < 0 || event.watch >= int(m_logs.size()))
        return true;
    File &f = m_logs[std::size_t(event.watch)];
    const QStringList row{isoTime(event.timeMs),
                          event.fired ? QStringLiteral("fired") : QStringLiteral("cleared"),
                          watchSeverityName(event.severity),
                          QString::number(event.rule),
                          csvField(event.point),
                          QString::number(event.value, 'g', 10),
                          csvField(event.message),
                          QString::number(event.firedCount)};
    const QByteArray line = (row.join(QLatin1Char(',')) + QLatin1Char('\n')).toUtf8();
    if (!writeRow(f.events, fileStem(f.watch.name) + QStringLiteral("-events"), eventHeader(), event.timeMs, line, error))
        return false;
    return maybeFlush(event.timeMs, error);
}

bool WatchCsvLog::appendNote(int watch, qint64 timeMs, const QString &event, quint64 rows, const QString &message, QString *error)
{
    if (watch < 0 || watch >= int(m_logs.size()))
        return true;
    File &f = m_logs[std::size_t(watch)];
    const QStringList row{isoTime(timeMs), csvField(event), watchSeverityName(WatchSeverity::Warning), QString(), QString(),
                          QString::number(rows), csvField(message), QString()};
    const QByteArray line = (row.join(QLatin1Char(',')) + QLatin1Char('\n')).toUtf8();
    if (!writeRow(f.events, fileStem(f.watch.name) + QStringLiteral("-events"), eventHeader(), timeMs, line, error))
        return false;
    return maybeFlush(timeMs, error);
}

bool WatchCsvLog::maybeFlush(qint64 timeMs, QString *error)
{
    if (timeMs - m_lastFlushMs < 1000)
        return true;
    m_lastFlushMs = timeMs;
    return flush(error);
}

bool WatchCsvLog::flushOutput(Output &out, QString *error)
{
    if (!out.file)
        return true;
    const quint64 rows = std::exchange(out.unflushedRows, 0);
    if (out.file->flush())
        return true;
    m_lostRows += rows;
    if (error)
        *error = QStringLiteral("%1: cannot be written: %2").arg(out.file->fileName(), out.file->errorString());
    return false;
}

bool WatchCsvLog::flush(QString *error)
{
    bool ok = true;
    for (File &f : m_logs) {
        ok = flushOutput(f.values, ok ? error : nullptr) && ok;
        ok = flushOutput(f.events, ok ? error : nullptr) && ok;
    }
    return ok;
}

void WatchCsvLog::close()
{
    for (File &f : m_logs) {
        for (Output *out : {&f.values, &f.events}) {
            if (out->file) {
                flushOutput(*out, nullptr);
                out->file->close();
                out->file.reset();
            }
        }
    }
}

} // namespace mbscope
