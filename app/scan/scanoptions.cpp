#include "scan/scanoptions.h"

#include "common/targetoptions.h"
#include "poll/profilelimits.h"

#include "time/duration.h"

#include <QtCore/QFile>
#include <QtCore/QSaveFile>
#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

QString optionName(const QCommandLineOption &option)
{
    return QStringLiteral("--") + option.names().constFirst();
}

} // namespace

bool ScanOptionReader::range(const QCommandLineOption &option, int low, int high, int *first, int *last) const
{
    if (!parser.isSet(option))
        return true;
    const QString text = parser.value(option).trimmed();
    const QStringList parts = text.split(QLatin1Char('-'));
    if (parts.size() > 2 || text.isEmpty()) {
        err << "mbscope " << command << ": " << optionName(option) << " '" << text << "': expected FIRST-LAST (e.g. 1-247) or one number\n";
        return false;
    }
    const IntegerResult a = parseInteger(optionName(option), parts.constFirst(), low, high);
    const IntegerResult b = parseInteger(optionName(option), parts.constLast(), low, high);
    if (!a.ok || !b.ok) {
        err << "mbscope " << command << ": " << (a.ok ? b.error : a.error) << '\n';
        return false;
    }
    if (a.value > b.value) {
        err << "mbscope " << command << ": " << optionName(option) << " '" << text << "': the first is above the last\n";
        return false;
    }
    *first = int(a.value);
    *last = int(b.value);
    return true;
}

bool ScanOptionReader::durationMs(const QCommandLineOption &option, qint64 lowMs, qint64 highMs, qint64 *ms) const
{
    if (!parser.isSet(option))
        return true;
    const DurationResult d = parseDuration(parser.value(option));
    if (!d.ok()) {
        err << "mbscope " << command << ": " << optionName(option) << ": " << d.error << '\n';
        return false;
    }
    const qint64 value = d.ns / 1'000'000;
    if (value < lowMs || value > highMs) {
        err << "mbscope " << command << ": " << optionName(option) << ' ' << parser.value(option) << " is out of range: expected "
            << lowMs << " ms to " << highMs << " ms\n";
        return false;
    }
    *ms = value;
    return true;
}

bool ScanOptionReader::integer(const QCommandLineOption &option, qint64 low, qint64 high, qint64 *value) const
{
    if (!parser.isSet(option))
        return true;
    const IntegerResult r = parseInteger(optionName(option), parser.value(option), low, high);
    if (!r.ok) {
        err << "mbscope " << command << ": " << r.error << '\n';
        return false;
    }
    *value = r.value;
    return true;
}

bool ScanOptionReader::integers(const QCommandLineOption &option, qint64 low, qint64 high, QList<qint64> *values) const
{
    if (!parser.isSet(option))
        return true;
    QList<qint64> out;
    for (const QString &part : parser.value(option).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const IntegerResult r = parseInteger(optionName(option), part, low, high);
        if (!r.ok) {
            err << "mbscope " << command << ": " << r.error << '\n';
            return false;
        }
        out.append(r.value);
    }
    if (out.isEmpty()) {
        err << "mbscope " << command << ": " << optionName(option) << " is empty: expected a comma-separated list\n";
        return false;
    }
    *values = out;
    return true;
}

bool writeScanFile(const QString &path, const QByteArray &bytes, const char *what, QTextStream &err)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        err << "mbscope scan: cannot write the " << what << " to " << path << ": " << file.errorString() << '\n';
        return false;
    }
    err << "mbscope scan: " << what << " written to " << path << '\n';
    return true;
}

bool readProfileToMerge(const QString &path, const char *what, QByteArray *json, QTextStream &err)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        err << "mbscope scan: --profile-out " << path << ": cannot be read (" << file.errorString() << "): " << what
            << " merged into an existing profile, such as the one mbscope scan --map UNIT --profile-out FILE writes\n";
        return false;
    }
    *json = file.readAll();
    if (const QString problem = ProfileLimits::loadProblem(*json, path); !problem.isEmpty()) {
        err << "mbscope scan: --profile-out " << path << ": not a profile the simulator loads, so nothing is merged into it:\n"
            << problem << '\n';
        return false;
    }
    return true;
}

bool mergeIntoProfileFile(const QString &path, const ProfileMergeFunction &merge, const char *written, QTextStream &err)
{
    QByteArray profile; // read again: it was checked before the scan, and may have changed since
    if (!readProfileToMerge(path, "what the scan found is", &profile, err))
        return false;
    QString said;
    QString problem;
    const QByteArray merged = merge(profile, &said, &problem);
    if (problem.isEmpty())
        problem = ProfileLimits::loadProblem(merged, path);
    if (!problem.isEmpty()) {
        err << "mbscope scan: --profile-out " << path << ": nothing merged: " << problem << '\n';
        return false;
    }
    err << "mbscope scan: " << said << '\n';
    return writeScanFile(path, merged, written, err);
}

} // namespace mbscope::app
