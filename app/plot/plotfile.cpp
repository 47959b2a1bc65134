#include "plot/plotfile.h"

#ifdef MBSCOPE_HAVE_UI
#include "common/plotsaver.h"
#endif

namespace mbscope::app {

#ifdef MBSCOPE_HAVE_UI
QString PlotFile::formatProblem(const QString &path)
{
    return PlotSaver::formatProblem(path);
}

bool PlotFile::save(QCustomPlot &plot, const QString &path, int width, int height, QString *error)
{
    return PlotSaver::save(plot, path, width, height, error);
}
#else
QString PlotFile::formatProblem(const QString &path)
{
    return QStringLiteral("'%1': this mbscope was built without the GUI (MBSCOPE_BUILD_UI=OFF), so it draws no plots")
        .arg(path);
}

bool PlotFile::save(QCustomPlot &, const QString &path, int, int, QString *error)
{
    *error = formatProblem(path);
    return false;
}
#endif

} // namespace mbscope::app
