#pragma once

#include <QtCore/QString>

class QCustomPlot;

namespace mbscope::app {

// Saves a QCustomPlot in the format its file name says: .png (savePng), .pdf (savePdf, vector)
// or .svg (QSvgGenerator from Qt SVG, vector; in a build without Qt SVG the error says so).
class PlotFile
{
public:
    // Empty when the name ends in a format mbscope writes, else what is wrong ("'x.gif': ...").
    [[nodiscard]] static QString formatProblem(const QString &path);
    [[nodiscard]] static bool save(QCustomPlot &plot, const QString &path, int width, int height, QString *error);
};

} // namespace mbscope::app
