#include "common/outputpath.h"

#include "plot/plotfile.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>

namespace mbscope::app {

QString OutputPath::problem(const QString &option, const QString &path, const QString &example, bool force, const QString &what)
{
    if (path == QLatin1String("-"))
        return {};
    const QFileInfo file(path);
    if (path.isEmpty() || file.isDir())
        return QStringLiteral("%1 '%2' is not a file name: expected e.g. %3").arg(option, path, example);
    const QFileInfo folder(file.absolutePath());
    const QString where = QDir::toNativeSeparators(file.absoluteFilePath());
    if (!folder.isDir())
        return QStringLiteral("%1: cannot write %2: the folder does not exist").arg(option, where);
    // Only a regular file holds something to lose: /dev/null or a FIFO is written as it is.
    if (file.exists() && file.isFile() && !force)
        return QStringLiteral("%1: %2 exists: %3 is never overwritten (give another name, or --force to replace it)")
            .arg(option, where, what);
    if (!folder.isWritable() || (file.exists() && !file.isWritable()))
        return QStringLiteral("%1: cannot write %2: permission denied").arg(option, where);
    // The permission bits say little (root passes them all, /proc looks writable): the file itself
    // answers. A new file is created and removed again; one that exists is opened, not truncated.
    QFile probe(path);
    const bool existed = file.exists();
    if (!probe.open(existed ? QIODevice::ReadWrite | QIODevice::Append : QIODevice::WriteOnly | QIODevice::NewOnly))
        return QStringLiteral("%1: cannot write %2: %3").arg(option, where, probe.errorString());
    probe.close();
    if (!existed)
        probe.remove();
    return {};
}

QString OutputPath::plotProblem(const QString &option, const QString &path, bool force)
{
    const QString format = PlotFile::formatProblem(path);
    if (!format.isEmpty())
        return option + QStringLiteral(": ") + format;
    return problem(option, path, option + QStringLiteral(" latency.png"), force);
}

QCommandLineOption OutputPath::forceOption()
{
    return QCommandLineOption(QStringLiteral("force"), QStringLiteral("Replace output files that exist (every output file is "
                                                                      "refused when it exists, unless this is given)."));
}

} // namespace mbscope::app
