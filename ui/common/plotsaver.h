#pragma once

#include <QtCore/QString>

class QCustomPlot;

namespace mbscope {

// Writes a QCustomPlot to a file in the format its name says: .png (raster), .pdf (vector) or
// .svg (vector, through Qt SVG; a build without Qt SVG refuses .svg and says why). Shared by the
// window's plots and the CLI's --histogram / --timeseries, so both write the same files.
class PlotSaver
{
public:
    // Empty when the name ends in a format mbscope writes, else what is wrong ("'x.gif': ...").
    [[nodiscard]] static QString formatProblem(const QString &path);
    // The file dialog's filter list ("PNG image (*.png);;SVG ...").
    [[nodiscard]] static QString fileFilter();
    [[nodiscard]] static bool save(QCustomPlot &plot, const QString &path, int width, int height, QString *error);
};

} // namespace mbscope
