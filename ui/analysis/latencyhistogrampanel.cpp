#include "latencyhistogrampanel.h"

#include <iterator>
#include <utility>

#include "common/csvexportaction.h"
#include "common/histogramchart.h"
#include "latencystatisticsmodel.h"
#include "common/plotexportmenu.h"

#include <QtGui/QAction>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>
#include <qcustomplot.h>

namespace mbscope {

LatencyHistogramPanel::LatencyHistogramPanel(LatencyRuns *runs, QWidget *parent)
    : QWidget(parent)
    , m_runs(runs)
    , m_plot(new QCustomPlot(this))
    , m_model(new LatencyStatisticsModel(this))
    , m_table(new QTableView(this))
    , m_export(new PlotExportMenu(m_plot, QStringLiteral("latency-histogram")))
    , m_csv(new CsvExportAction(m_model, QStringLiteral("latency-statistics"), this))
    , m_runChoice(new QComboBox(this))
    , m_itemChoice(new QComboBox(this))
    , m_scaleChoice(new QComboBox(this))
    , m_summary(new QLabel(this))
{
    m_plot->setObjectName(QStringLiteral("latencyHistogramPlot"));
    m_plot->setMinimumSize(300, 200);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_table->setObjectName(QStringLiteral("latencyStatisticsTable"));
    m_summary->setObjectName(QStringLiteral("latencySummary"));
    m_table->setModel(m_model);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAlternatingRowColors(true);
    m_table->setMinimumWidth(300); // the figures and their values in view beside the plot
    m_table->addAction(m_csv);
    m_table->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_runChoice->setObjectName(QStringLiteral("runChoice"));
    m_runChoice->setToolTip(tr("Which run to show: the current poll, the kept reference or an opened capture"));
    m_itemChoice->setObjectName(QStringLiteral("itemChoice"));
    m_itemChoice->setToolTip(tr("All transactions, or those of one request item of the poll"));
    m_scaleChoice->setObjectName(QStringLiteral("scaleChoice"));
    m_scaleChoice->addItem(tr("Linear bins"), int(LatencyBinning::Scale::Linear));
    m_scaleChoice->addItem(tr("Logarithmic bins"), int(LatencyBinning::Scale::Logarithmic));
    m_scaleChoice->setToolTip(tr("Bins of equal width, or bins a constant factor apart for a long tail"));
    refillRunChoice();
    refillItemChoice();

    auto *keep = new QAction(tr("&Keep as reference"), this);
    keep->setToolTip(tr("Keep the current poll's figures to compare later runs with (Compare tab)"));
    connect(keep, &QAction::triggered, m_runs, &LatencyRuns::keepReference);
    auto *fit = new QAction(tr("&Fit"), this);
    fit->setToolTip(tr("Show the whole histogram again after zooming or panning"));
    connect(fit, &QAction::triggered, this, &LatencyHistogramPanel::fitView);

    auto *tools = new QToolBar(this);
    m_tools = tools;
    tools->addWidget(m_runChoice);
    tools->addWidget(m_itemChoice);
    tools->addWidget(m_scaleChoice);
    tools->addAction(fit);
    tools->addAction(keep);
    tools->addSeparator();
    tools->addAction(m_export->saveAction());
    tools->addAction(m_export->copyAction());
    tools->addAction(m_csv);
    tools->addSeparator();
    tools->addWidget(m_summary);

    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(m_plot);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tools);
    layout->addWidget(splitter, 1);

    connect(m_runChoice, &QComboBox::activated, this, [this](int index) {
        setRun(LatencyRuns::Run(m_runChoice->itemData(index).toInt()));
    });
    connect(m_itemChoice, &QComboBox::activated, this, [this](int index) { setItem(m_itemChoice->itemData(index).toInt()); });
    connect(m_scaleChoice, &QComboBox::activated, this, [this](int index) {
        setScale(LatencyBinning::Scale(m_scaleChoice->itemData(index).toInt()));
    });
    connect(m_runs, &LatencyRuns::runsChanged, this, &LatencyHistogramPanel::refillRunChoice);
    connect(m_runs, &LatencyRuns::changed, this, [this](LatencyRuns::Run changed) {
        if (changed == m_run)
            scheduleRedraw();
    });
    connect(m_export, &PlotExportMenu::saved, this, &LatencyHistogramPanel::exported);
    connect(m_csv, &CsvExportAction::saved, this, &LatencyHistogramPanel::exported);

    // Zooming or panning by hand: the user is looking at something, redraws leave the view alone.
    const auto byHand = [this]() {
        if (!m_drawing)
            m_viewByHand = true;
    };
    connect(m_plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this, byHand);
    connect(m_plot->yAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this, byHand);

    m_redrawTimer.setSingleShot(true);
    m_redrawTimer.setInterval(kRedrawMs);
    connect(&m_redrawTimer, &QTimer::timeout, this, &LatencyHistogramPanel::redraw);
    redraw();
}

void LatencyHistogramPanel::setRun(LatencyRuns::Run run)
{
    if (!m_runs->has(run))
        return;
    m_run = run;
    m_runChoice->setCurrentIndex(m_runChoice->findData(int(run)));
    m_item = -1;
    m_viewByHand = false;
    redraw();
}

void LatencyHistogramPanel::setItem(int item)
{
    m_item = item;
    m_viewByHand = false;
    redraw();
}

void LatencyHistogramPanel::setScale(LatencyBinning::Scale scale)
{
    m_scale = scale;
    m_scaleChoice->setCurrentIndex(m_scaleChoice->findData(int(scale)));
    m_viewByHand = false;
    redraw();
}

void LatencyHistogramPanel::showTransactions(const QString &title, const QList<Transaction> &transactions)
{
    m_runs->setCapture(title, transactions);
    setRun(LatencyRuns::Capture);
}

void LatencyHistogramPanel::addSourceChoice(QWidget *choice)
{
    QAction *first = m_tools->actions().value(0);
    m_tools->insertWidget(first, choice);
    if (first)
        m_tools->insertSeparator(first);
}

void LatencyHistogramPanel::redrawNow()
{
    if (m_redrawTimer.isActive())
        redraw();
}

void LatencyHistogramPanel::fitView()
{
    m_viewByHand = false;
    redraw();
}

void LatencyHistogramPanel::scheduleRedraw()
{
    if (!m_redrawTimer.isActive())
        m_redrawTimer.start();
}

void LatencyHistogramPanel::refillRunChoice()
{
    m_runChoice->clear();
    for (int run = 0; run < LatencyRuns::kRunCount; ++run) {
        if (m_runs->has(LatencyRuns::Run(run)))
            m_runChoice->addItem(m_runs->title(LatencyRuns::Run(run)), run);
    }
    m_runChoice->setCurrentIndex(m_runChoice->findData(int(m_run)));
}

void LatencyHistogramPanel::refillItemChoice()
{
    const int items = m_runs->statistics(m_run).itemCount();
    if (m_itemChoice->count() == items + 1 && m_itemChoice->currentData().toInt() == m_item)
        return;
    m_itemChoice->clear();
    m_itemChoice->addItem(tr("Overall"), -1);
    for (int item = 0; item < items; ++item)
        m_itemChoice->addItem(LatencyRuns::itemTitle(item), item);
    const int index = m_itemChoice->findData(m_item);
    if (index < 0) // that item is not in this run
        m_item = -1;
    m_itemChoice->setCurrentIndex(qMax(0, index));
}

void LatencyHistogramPanel::redraw()
{
    m_redrawTimer.stop();
    ++m_redraws;
    refillItemChoice();
    const Statistics &statistics = m_runs->statistics(m_run, m_item);
    const LatencySamples &latency = statistics.latency();
    m_histogram = LatencyBinning::bin(latency, m_scale);

    QList<HistogramChart::Series> series;
    QList<HistogramChart::Marker> markers;
    if (m_histogram.isValid()) {
        series.append({QString(), m_histogram.edgesNs(), m_histogram.counts(), m_histogram.isLogarithmic()});
        const HistogramChart::Unit unit = HistogramChart::unitFor(m_histogram.edgesNs().back());
        const auto at = [&unit](qint64 ns) { return QLocale().toString(double(ns) / unit.ns, 'f', unit.ns >= 1e6 ? 3 : 1); };
        const std::pair<QString, qint64> marks[] = {
            {tr("min"), latency.minNs()},
            {tr("median"), latency.medianNs()},
            {tr("p95"), latency.percentileNs(95)},
            {tr("p99"), latency.percentileNs(99)},
            {tr("max"), latency.maxNs()},
        };
        // Marks at one latency share one label ("min = median = max 1.205 ms"): with one sample,
        // or a few, five labels would be drawn over each other.
        QStringList names;
        for (size_t i = 0; i < std::size(marks); ++i) {
            names << marks[i].first;
            if (i + 1 < std::size(marks) && marks[i + 1].second == marks[i].second)
                continue;
            markers.append({tr("%1 %2 %3").arg(names.join(QStringLiteral(" = ")), at(marks[i].second), unit.name),
                            double(marks[i].second), QColor()});
            names.clear();
        }
    }
    m_drawing = true;
    const QCPRange x = m_plot->xAxis->range();
    const QCPRange y = m_plot->yAxis->range();
    HistogramChart::draw(*m_plot, series, markers);
    if (m_viewByHand) {
        m_plot->xAxis->setRange(x);
        m_plot->yAxis->setRange(y);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    m_drawing = false;

    m_model->setColumns({{tr("%1, %2").arg(m_runs->title(m_run), LatencyRuns::itemTitle(m_item)), &statistics}});
    QString summary = tr("%1 transactions, %2 answered").arg(statistics.count()).arg(latency.count());
    // What the latency is measured from, and a warning when a serial link does not keep to its
    // baud rate (issue 19: answers over a pty came "under 1 ms" after a computed end of
    // transmission the pty never honoured).
    if (statistics.measuredFromLineEnd() > 0 && statistics.measuredFromWrite() == 0)
        summary += tr("; latency from the computed end of each request's transmission");
    else if (statistics.measuredFromLineEnd() > 0)
        summary += tr("; latency from the computed end of transmission (%1) or the write (%2)")
                       .arg(statistics.measuredFromLineEnd())
                       .arg(statistics.measuredFromWrite());
    else if (!latency.isEmpty())
        summary += tr("; latency from each request's write");
    QString warning;
    if (statistics.outranLine() > 0) {
        summary += tr("; warning: %1 answers faster than the serial line").arg(statistics.outranLine());
        warning = tr("%1 answers came before the serial line could have carried the request and the answer at its baud "
                     "rate: the link does not honour it (a pseudo terminal, or a USB adapter that buffers). Their "
                     "latency is measured from the write.")
                      .arg(statistics.outranLine());
    }
    m_summary->setText(summary);
    m_summary->setToolTip(warning);
}

} // namespace mbscope
