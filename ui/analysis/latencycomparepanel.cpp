#include "latencycomparepanel.h"

#include "common/csvexportaction.h"
#include "common/histogramchart.h"
#include "latencystatisticsmodel.h"
#include "common/plotexportmenu.h"

#include <QtCore/QPoint>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace mbscope {

namespace {

// A side as combo box data: run and item in a QPoint.
QVariant sideData(const LatencyComparePanel::Side &side)
{
    return QPoint(int(side.run), side.item);
}

LatencyComparePanel::Side sideOf(const QVariant &data)
{
    const QPoint p = data.toPoint();
    return {LatencyRuns::Run(p.x()), p.y()};
}

} // namespace

LatencyComparePanel::LatencyComparePanel(LatencyRuns *runs, QWidget *parent)
    : QWidget(parent)
    , m_runs(runs)
    , m_plot(new QCustomPlot(this))
    , m_model(new LatencyStatisticsModel(this))
    , m_table(new QTableView(this))
    , m_export(new PlotExportMenu(m_plot, QStringLiteral("latency-compare")))
    , m_csv(new CsvExportAction(m_model, QStringLiteral("latency-compare"), this))
    , m_choices{new QComboBox(this), new QComboBox(this)}
    , m_scaleChoice(new QComboBox(this))
{
    m_plot->setObjectName(QStringLiteral("latencyComparePlot"));
    m_plot->setMinimumSize(300, 200);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    // The legend below the axes: inside them it would cover the markers' labels.
    auto *legendRow = new QCPLayoutGrid;
    m_plot->plotLayout()->addElement(1, 0, legendRow);
    legendRow->setMargins(QMargins(5, 0, 5, 5));
    legendRow->addElement(0, 0, m_plot->legend);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->plotLayout()->setRowStretchFactor(1, 0.001);
    m_table->setObjectName(QStringLiteral("latencyCompareTable"));
    m_table->setModel(m_model);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAlternatingRowColors(true);
    m_table->setMinimumWidth(400); // the figures and their values in view beside the plot
    m_table->addAction(m_csv);
    m_table->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_choices[0]->setObjectName(QStringLiteral("firstChoice"));
    m_choices[1]->setObjectName(QStringLiteral("secondChoice"));
    for (QComboBox *choice : m_choices) {
        choice->setToolTip(tr("A run (current poll, reference, capture) and a request item, or all of its transactions"));
        choice->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        connect(choice, &QComboBox::activated, this, [this] {
            setSides(sideOf(m_choices[0]->currentData()), sideOf(m_choices[1]->currentData()));
        });
    }
    m_scaleChoice->addItem(tr("Linear bins"), int(LatencyBinning::Scale::Linear));
    m_scaleChoice->addItem(tr("Logarithmic bins"), int(LatencyBinning::Scale::Logarithmic));
    connect(m_scaleChoice, &QComboBox::activated, this, [this](int index) {
        setScale(LatencyBinning::Scale(m_scaleChoice->itemData(index).toInt()));
    });

    auto *tools = new QToolBar(this);
    tools->addWidget(m_choices[0]);
    tools->addWidget(new QLabel(tr("against"), this));
    tools->addWidget(m_choices[1]);
    tools->addWidget(m_scaleChoice);
    tools->addSeparator();
    tools->addAction(m_export->saveAction());
    tools->addAction(m_export->copyAction());
    tools->addAction(m_csv);

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

    connect(m_runs, &LatencyRuns::runsChanged, this, &LatencyComparePanel::scheduleRedraw);
    connect(m_runs, &LatencyRuns::changed, this, [this](LatencyRuns::Run changed) {
        if (changed == m_sides[0].run || changed == m_sides[1].run)
            scheduleRedraw();
    });
    connect(m_export, &PlotExportMenu::saved, this, &LatencyComparePanel::exported);
    connect(m_csv, &CsvExportAction::saved, this, &LatencyComparePanel::exported);

    m_redrawTimer.setSingleShot(true);
    m_redrawTimer.setInterval(kRedrawMs);
    connect(&m_redrawTimer, &QTimer::timeout, this, &LatencyComparePanel::redraw);
    redraw();
}

void LatencyComparePanel::setSides(Side first, Side second)
{
    m_sides[0] = first;
    m_sides[1] = second;
    redraw();
}

void LatencyComparePanel::setScale(LatencyBinning::Scale scale)
{
    m_scale = scale;
    m_scaleChoice->setCurrentIndex(m_scaleChoice->findData(int(scale)));
    redraw();
}

void LatencyComparePanel::redrawNow()
{
    if (m_redrawTimer.isActive())
        redraw();
}

void LatencyComparePanel::scheduleRedraw()
{
    if (!m_redrawTimer.isActive())
        m_redrawTimer.start();
}

QString LatencyComparePanel::sideTitle(const Side &side) const
{
    return tr("%1, %2").arg(m_runs->title(side.run), LatencyRuns::itemTitle(side.item));
}

// Every present run, overall and each of its items; a side whose run or item is not (or no
// longer) there is still listed, so the choice never jumps by itself.
void LatencyComparePanel::refillChoices()
{
    QList<Side> sides;
    for (int run = 0; run < LatencyRuns::kRunCount; ++run) {
        if (!m_runs->has(LatencyRuns::Run(run)))
            continue;
        const int items = m_runs->statistics(LatencyRuns::Run(run)).itemCount();
        for (int item = -1; item < items; ++item)
            sides.append({LatencyRuns::Run(run), item});
    }
    for (const Side &side : m_sides) {
        if (!sides.contains(side))
            sides.append(side);
    }
    for (int k = 0; k < 2; ++k) {
        QComboBox *choice = m_choices[k];
        bool same = choice->count() == sides.size();
        for (int i = 0; same && i < choice->count(); ++i)
            same = sideOf(choice->itemData(i)) == sides.at(i) && choice->itemText(i) == sideTitle(sides.at(i));
        if (!same) {
            choice->clear();
            for (const Side &side : sides)
                choice->addItem(sideTitle(side), sideData(side));
        }
        choice->setCurrentIndex(choice->findData(sideData(m_sides[k])));
    }
}

void LatencyComparePanel::redraw()
{
    m_redrawTimer.stop();
    refillChoices();
    const Statistics &first = m_runs->statistics(m_sides[0].run, m_sides[0].item);
    const Statistics &second = m_runs->statistics(m_sides[1].run, m_sides[1].item);
    m_histograms = LatencyBinning::binCommon({&first.latency(), &second.latency()}, m_scale);

    QList<HistogramChart::Series> series;
    QList<HistogramChart::Marker> markers;
    const Statistics *statistics[2] = {&first, &second};
    if (m_histograms.constFirst().isValid()) {
        const HistogramChart::Unit unit = HistogramChart::unitFor(m_histograms.constFirst().edgesNs().back());
        for (int k = 0; k < 2; ++k) {
            const Histogram &h = m_histograms.at(k);
            const LatencySamples &latency = statistics[k]->latency();
            series.append({tr("%1 (%2 answered)").arg(sideTitle(m_sides[k])).arg(latency.count()), h.edgesNs(), h.counts(),
                           h.isLogarithmic()});
            if (!latency.isEmpty())
                markers.append({tr("median %1 %2")
                                    .arg(QLocale().toString(double(latency.medianNs()) / unit.ns, 'f', unit.ns >= 1e6 ? 3 : 1),
                                         unit.name),
                                double(latency.medianNs()), HistogramChart::seriesColour(k)});
        }
    }
    HistogramChart::draw(*m_plot, series, markers);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    m_model->setColumns({{sideTitle(m_sides[0]), &first}, {sideTitle(m_sides[1]), &second}});
}

} // namespace mbscope
