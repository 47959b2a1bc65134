#pragma once

#include <QtCore/QString>

class QCustomPlot;

namespace mbscope::app {

// The CLI's side of PlotSaver (ui/common/plotsaver.h, shared with the window): a QCustomPlot saved in the
// format its file name says; in a build without the GUI every plot is refused, saying why.
class PlotFile
{
public:
    // Empty when the name ends in a format mbscope writes, else what is wrong ("'x.gif': ...").
    [[nodiscard]] static QString formatProblem(const QString &path);
    [[nodiscard]] static bool save(QCustomPlot &plot, const QString &path, int width, int height, QString *error);
};

} // namespace mbscope::app
