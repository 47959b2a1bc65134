#include "outputpath.h"

#include "plotfile.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>

namespace mbscope::app {

QString OutputPath::problem(const QString &option, const QString &path, const QString &example)
{
    const QFileInfo file(path);
    if (path.isEmpty() || file.isDir())
        return QStringLiteral("%1 '%2' is not a file name: expected e.g. %3").arg(option, path, example);
    const QFileInfo folder(file.absolutePath());
    const QString where = QDir::toNativeSeparators(file.absoluteFilePath());
    if (!folder.isDir())
        return QStringLiteral("%1: cannot write %2: the folder does not exist").arg(option, where);
    if (!folder.isWritable() || (file.exists() && !file.isWritable()))
        return QStringLiteral("%1: cannot write %2: permission denied").arg(option, where);
    return {};
}

QString OutputPath::plotProblem(const QString &option, const QString &path)
{
    const QString format = PlotFile::formatProblem(path);
    if (!format.isEmpty())
        return option + QStringLiteral(": ") + format;
    return problem(option, path, option + QStringLiteral(" latency.png"));
}

} // namespace mbscope::app
