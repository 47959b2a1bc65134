#include "plotcursor.h"

#include <QtGui/QMouseEvent>
#include <qcustomplot.h>

#include <cmath>

namespace mbscope {

namespace {

QString number(double value)
{
    return QString::number(value, 'g', 6);
}

} // namespace

PlotCursor::PlotCursor(QCustomPlot *plot)
    : QObject(plot)
    , m_plot(plot)
    , m_line(new QCPItemStraightLine(plot))
    , m_text(new QCPItemText(plot))
{
    m_line->setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
    m_line->setSelectable(false);
    m_text->setSelectable(false);
    m_text->position->setTypeX(QCPItemPosition::ptPlotCoords);
    m_text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_text->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_text->setTextAlignment(Qt::AlignLeft);
    m_text->setPadding(QMargins(5, 3, 5, 3));
    m_text->setBrush(QColor(255, 255, 255, 225));
    m_text->setPen(QPen(QColor(150, 150, 150)));
    m_text->setFont(QFont(plot->font().family(), 8));
    hide();

    connect(plot, &QCustomPlot::mousePress, this, &PlotCursor::onMousePress);
    connect(plot, &QCustomPlot::mouseMove, this, &PlotCursor::onMouseMove);
    connect(plot, &QCustomPlot::mouseRelease, this, &PlotCursor::onMouseRelease);
    connect(plot, &QCustomPlot::mouseDoubleClick, this, &PlotCursor::onMouseDoubleClick);
    // Live data changes what the cursor reads without the cursor moving.
    connect(plot, &QCustomPlot::beforeReplot, this, &PlotCursor::refresh);
}

void PlotCursor::setValueFormatter(QCPGraph *graph, Formatter formatter)
{
    m_valueFormats.insert(graph, std::move(formatter));
}

void PlotCursor::setLabel(QCPGraph *graph, const QString &label)
{
    m_labels.insert(graph, label);
}

void PlotCursor::setX(double x)
{
    m_pinned = true;
    moveTo(x);
}

void PlotCursor::unpin()
{
    m_pinned = false;
}

void PlotCursor::hide()
{
    m_shown = false;
    m_pinned = false;
    m_line->setVisible(false);
    m_text->setVisible(false);
}

bool PlotCursor::valueAt(const QCPGraph *graph, double x, double *value) const
{
    const QSharedPointer<QCPGraphDataContainer> data = graph->data();
    if (data->isEmpty())
        return false;
    if (graph->lineStyle() != QCPGraph::lsNone) {
        auto after = data->findEnd(x, false); // first sample later than x
        if (after == data->constBegin())
            return false;
        *value = (after - 1)->value;
        return true;
    }
    auto it = data->findBegin(x, false); // first point at or after x
    const QCPAxis *keys = graph->keyAxis();
    double best = PlotCursor::kPickPixels + 1;
    const double linePixel = keys->coordToPixel(x);
    for (auto candidate : {it, it == data->constBegin() ? data->constEnd() : it - 1}) {
        if (candidate == data->constEnd())
            continue;
        const double distance = std::abs(keys->coordToPixel(candidate->key) - linePixel);
        if (distance < best) {
            best = distance;
            *value = candidate->value;
        }
    }
    return best <= PlotCursor::kPickPixels;
}

QString PlotCursor::readout() const
{
    if (!m_shown)
        return {};
    QStringList lines;
    lines.append(m_xFormat ? m_xFormat(m_x) : number(m_x));
    for (int i = 0; i < m_plot->graphCount(); ++i) {
        const QCPGraph *graph = m_plot->graph(i);
        double value = 0;
        if (!graph->visible() || graph->name().isEmpty() || !valueAt(graph, m_x, &value))
            continue;
        const auto format = m_valueFormats.constFind(graph);
        const QString text = format != m_valueFormats.constEnd() && *format ? (*format)(value) : number(value);
        const QString label = m_labels.value(graph, graph->name());
        lines.append(text.isEmpty() ? label : tr("%1: %2").arg(label, text));
    }
    return lines.join(QLatin1Char('\n'));
}

void PlotCursor::moveTo(double x)
{
    m_x = x;
    m_shown = true;
    m_line->setVisible(true);
    m_text->setVisible(true);
    m_line->point1->setCoords(x, 0);
    m_line->point2->setCoords(x, 1);
    refresh();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotCursor::refresh()
{
    if (!m_shown)
        return;
    const QString text = readout();
    // The readout stays inside the plot: right of the line, or left of it near the right edge.
    const QCPRange range = m_plot->xAxis->range();
    const bool nearRight = m_x > range.lower + 0.7 * range.size();
    m_text->setPositionAlignment((nearRight ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
    m_text->position->setCoords(m_x, 0.02);
    if (text != m_text->text()) {
        m_text->setText(text);
        Q_EMIT readoutChanged(text);
    }
}

void PlotCursor::onMousePress(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return;
    m_pressed = true;
    m_pressAt = event->position();
}

void PlotCursor::onMouseMove(QMouseEvent *event)
{
    if (m_pinned || m_pressed || !m_plot->axisRect()->rect().contains(event->position().toPoint()))
        return;
    moveTo(m_plot->xAxis->pixelToCoord(event->position().x()));
}

void PlotCursor::onMouseRelease(QMouseEvent *event)
{
    if (!m_pressed || event->button() != Qt::LeftButton)
        return;
    m_pressed = false;
    // A drag pans the plot; only a click that stayed put places the cursor.
    if ((event->position() - m_pressAt).manhattanLength() > 4)
        return;
    setX(m_plot->xAxis->pixelToCoord(event->position().x()));
}

void PlotCursor::onMouseDoubleClick(QMouseEvent *event)
{
    m_pressed = false; // the release that ends a double click does not pin the cursor again
    unpin();
    moveTo(m_plot->xAxis->pixelToCoord(event->position().x()));
}

} // namespace mbscope
