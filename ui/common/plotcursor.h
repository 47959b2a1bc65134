#pragma once

#include <QtCore/QHash>
#include <QtCore/QObject>
#include <QtCore/QPointF>
#include <QtCore/QString>

#include <functional>

class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QMouseEvent;

namespace mbscope {

// A vertical cursor on a QCustomPlot that reads values: it follows the mouse until a click pins
// it (a click that did not drag: dragging pans), a double click lets it follow again. Its readout,
// drawn at the top of the line, gives x and, for each visible graph with data, the y there:
//   graphs drawn as lines: the latest sample at or before x (a polled value holds until the next)
//   graphs of points: the nearest point within kPickPixels of the line, else nothing
// Shared by the latency-over-time and register-trend panels; the plot keeps its own interactions
// (zoom with the wheel, pan by dragging).
class PlotCursor : public QObject
{
    Q_OBJECT

public:
    using Formatter = std::function<QString(double)>;
    static constexpr double kPickPixels = 24;

    explicit PlotCursor(QCustomPlot *plot);

    // How x and a graph's y read ("12.300 s", "-12.5 degC"); numbers to 6 digits otherwise.
    void setXFormatter(Formatter formatter) { m_xFormat = std::move(formatter); }
    void setValueFormatter(QCPGraph *graph, Formatter formatter);
    // The name the readout gives a graph when its legend name says more ("answered (120)");
    // a graph whose formatter gives an empty text reads as its label alone ("timeout").
    void setLabel(QCPGraph *graph, const QString &label);

    // Places and pins the cursor at x (plot coordinates), as a click does.
    void setX(double x);
    [[nodiscard]] double x() const { return m_x; }
    [[nodiscard]] bool isPinned() const { return m_pinned; }
    [[nodiscard]] bool isShown() const { return m_shown; }
    void unpin();
    void hide();

    // The readout as drawn, one line per value: "t = 12.300 s\nanswered: 4.12 ms".
    [[nodiscard]] QString readout() const;
    // The value a graph reads at the cursor, with whether it has one.
    [[nodiscard]] bool valueAt(const QCPGraph *graph, double x, double *value) const;

Q_SIGNALS:
    void readoutChanged(const QString &readout);

private:
    void onMousePress(QMouseEvent *event);
    void onMouseMove(QMouseEvent *event);
    void onMouseRelease(QMouseEvent *event);
    void onMouseDoubleClick(QMouseEvent *event);
    void moveTo(double x);
    void refresh();

    QCustomPlot *m_plot;
    QCPItemStraightLine *m_line;
    QCPItemText *m_text;
    Formatter m_xFormat;
    QHash<const QCPGraph *, Formatter> m_valueFormats;
    QHash<const QCPGraph *, QString> m_labels;
    double m_x = 0;
    bool m_shown = false;
    bool m_pinned = false;
    QPointF m_pressAt;
    bool m_pressed = false;
};

} // namespace mbscope
