#include "plotsaver.h"

#include <QtCore/QCoreApplication>
#include <qcustomplot.h>
#ifdef MBSCOPE_HAVE_SVG
#include <QtSvg/QSvgGenerator>
#endif

namespace mbscope {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("mbscope::PlotSaver", text);
}

bool endsWith(const QString &path, QLatin1StringView suffix)
{
    return path.endsWith(suffix, Qt::CaseInsensitive);
}

bool saveSvg(QCustomPlot &plot, const QString &path, int width, int height)
{
#ifdef MBSCOPE_HAVE_SVG
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(QSize(width, height));
    svg.setViewBox(QRect(0, 0, width, height));
    svg.setTitle(QStringLiteral("mbscope"));
    QCPPainter painter;
    if (!painter.begin(&svg))
        return false;
    plot.toPainter(&painter, width, height);
    return painter.end();
#else
    Q_UNUSED(plot);
    Q_UNUSED(path);
    Q_UNUSED(width);
    Q_UNUSED(height);
    return false;
#endif
}

} // namespace

QString PlotSaver::formatProblem(const QString &path)
{
    if (endsWith(path, QLatin1StringView(".png")) || endsWith(path, QLatin1StringView(".pdf")))
        return {};
    if (endsWith(path, QLatin1StringView(".svg"))) {
#ifdef MBSCOPE_HAVE_SVG
        return {};
#else
        return tr("'%1': this mbscope was built without Qt SVG (Debian: qt6-svg-dev), so it cannot write SVG; "
                  "use .png or .pdf")
            .arg(path);
#endif
    }
    return tr("'%1': the plot's format comes from the file name, which must end in .png, .svg or .pdf").arg(path);
}

QString PlotSaver::fileFilter()
{
    QString filter = tr("PNG image (*.png)");
#ifdef MBSCOPE_HAVE_SVG
    filter += QStringLiteral(";;") + tr("SVG drawing (*.svg)");
#endif
    filter += QStringLiteral(";;") + tr("PDF document (*.pdf)");
    return filter;
}

bool PlotSaver::save(QCustomPlot &plot, const QString &path, int width, int height, QString *error)
{
    const QString problem = formatProblem(path);
    if (!problem.isEmpty()) {
        *error = problem;
        return false;
    }
    bool saved = false;
    if (endsWith(path, QLatin1StringView(".png")))
        saved = plot.savePng(path, width, height);
    else if (endsWith(path, QLatin1StringView(".pdf")))
        saved = plot.savePdf(path, width, height);
    else
        saved = saveSvg(plot, path, width, height);
    if (!saved)
        *error = tr("cannot write %1").arg(path);
    return saved;
}

} // namespace mbscope
