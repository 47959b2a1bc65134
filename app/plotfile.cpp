#include "plotfile.h"

#ifdef MBSCOPE_HAVE_UI
#include <qcustomplot.h>
#endif
#ifdef MBSCOPE_HAVE_SVG
#include <QtSvg/QSvgGenerator>
#endif

namespace mbscope::app {

QString PlotFile::formatProblem(const QString &path)
{
    const QString lower = path.toLower();
    if (lower.endsWith(QLatin1String(".png")) || lower.endsWith(QLatin1String(".pdf")))
        return {};
    if (lower.endsWith(QLatin1String(".svg"))) {
#ifdef MBSCOPE_HAVE_SVG
        return {};
#else
        return QStringLiteral("'%1': this mbscope was built without Qt SVG (Debian: qt6-svg-dev), so it cannot write SVG; "
                              "use .png or .pdf")
            .arg(path);
#endif
    }
    return QStringLiteral("'%1': the plot's format comes from the file name, which must end in .png, .svg or .pdf").arg(path);
}

#ifdef MBSCOPE_HAVE_UI
bool PlotFile::save(QCustomPlot &plot, const QString &path, int width, int height, QString *error)
{
    const QString problem = formatProblem(path);
    if (!problem.isEmpty()) {
        *error = problem;
        return false;
    }
    const QString lower = path.toLower();
    bool saved = false;
    if (lower.endsWith(QLatin1String(".png"))) {
        saved = plot.savePng(path, width, height);
    } else if (lower.endsWith(QLatin1String(".pdf"))) {
        saved = plot.savePdf(path, width, height);
    } else {
#ifdef MBSCOPE_HAVE_SVG
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(QSize(width, height));
        svg.setViewBox(QRect(0, 0, width, height));
        svg.setTitle(QStringLiteral("mbscope"));
        QCPPainter painter;
        saved = painter.begin(&svg);
        if (saved) {
            plot.toPainter(&painter, width, height);
            saved = painter.end();
        }
#endif
    }
    if (!saved)
        *error = QStringLiteral("cannot write %1").arg(path);
    return saved;
}
#else
bool PlotFile::save(QCustomPlot &, const QString &, int, int, QString *error)
{
    *error = QStringLiteral("this mbscope was built without the GUI (MBSCOPE_BUILD_UI=OFF): no plots");
    return false;
}
#endif

} // namespace mbscope::app
