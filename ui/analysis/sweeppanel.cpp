#include "sweeppanel.h"

#include "common/csvexportaction.h"
#include "link/linkcontroller.h"
#include "common/plotexportmenu.h"
#include "sweeptablemodel.h"

#include <QtGui/QAction>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace mbscope {

namespace {

QCPGraph *addLine(QCustomPlot *plot, QCPAxis *valueAxis, const QColor &colour, Qt::PenStyle style,
                  QCPScatterStyle::ScatterShape shape)
{
    QCPGraph *graph = plot->addGraph(plot->xAxis, valueAxis);
    graph->setPen(QPen(colour, 2, style));
    graph->setScatterStyle(QCPScatterStyle(shape, colour, Qt::white, 7));
    return graph;
}

} // namespace

SweepPanel::SweepPanel(QWidget *parent)
    : QWidget(parent)
    , m_intervals(new QLineEdit(QStringLiteral("100, 200, 300, 333, 350, 400"), this))
    , m_count(new QSpinBox(this))
    , m_start(new QPushButton(tr("&Start sweep"), this))
    , m_stop(new QPushButton(tr("S&top"), this))
    , m_progress(new QProgressBar(this))
    , m_message(new QLabel(this))
    , m_plot(new QCustomPlot(this))
    , m_errorRate(addLine(m_plot, m_plot->yAxis, QColor(214, 39, 40), Qt::SolidLine, QCPScatterStyle::ssCircle))
    , m_median(addLine(m_plot, m_plot->yAxis2, QColor(31, 119, 180), Qt::SolidLine, QCPScatterStyle::ssDisc))
    , m_p95(addLine(m_plot, m_plot->yAxis2, QColor(31, 119, 180), Qt::DashLine, QCPScatterStyle::ssTriangle))
    , m_export(new PlotExportMenu(m_plot, QStringLiteral("sweep")))
    , m_model(new SweepTableModel(this))
    , m_table(new QTableView(this))
{
    m_intervals->setObjectName(QStringLiteral("sweepIntervals"));
    m_intervals->setToolTip(tr("Poll intervals in milliseconds, separated by commas; each is run in turn"));
    m_count->setRange(1, 1000000);
    m_count->setValue(50);
    m_count->setToolTip(tr("Transactions (poll cycles) at each interval"));
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_message->setObjectName(QStringLiteral("sweepMessage"));
    m_message->setWordWrap(true);
    connect(m_start, &QPushButton::clicked, this, &SweepPanel::start);
    connect(m_stop, &QPushButton::clicked, this, &SweepPanel::stop);

    auto *exportCsv = new CsvExportAction(m_model, QStringLiteral("sweep"), this);
    connect(exportCsv, &CsvExportAction::saved, this, &SweepPanel::showMessage);

    auto *settings = new QHBoxLayout;
    settings->addWidget(new QLabel(tr("Intervals (ms):"), this));
    settings->addWidget(m_intervals, 2);
    settings->addWidget(new QLabel(tr("Count per interval:"), this));
    settings->addWidget(m_count);
    settings->addWidget(m_start);
    settings->addWidget(m_stop);
    settings->addWidget(m_progress, 1);

    auto *tools = new QToolBar(this);
    tools->addAction(m_export->saveAction());
    tools->addAction(m_export->copyAction());
    tools->addAction(exportCsv);

    m_plot->setObjectName(QStringLiteral("sweepPlot"));
    m_plot->setMinimumSize(300, 200);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->xAxis->setLabel(tr("poll interval (ms)"));
    m_plot->yAxis->setLabel(tr("error rate (%)"));
    m_plot->yAxis2->setLabel(tr("latency (ms)"));
    m_plot->yAxis2->setVisible(true);
    m_plot->legend->setVisible(true);
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    m_errorRate->setName(tr("error rate (%)"));
    m_median->setName(tr("median latency (ms)"));
    m_p95->setName(tr("p95 latency (ms)"));
    m_plot->yAxis->setRange(0, 10);
    m_plot->yAxis2->setRange(0, 10);
    m_plot->xAxis->setRange(0, 500);

    m_table->setObjectName(QStringLiteral("sweepTable"));
    m_table->setModel(m_model);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto *split = new QSplitter(this);
    split->addWidget(m_plot);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(settings);
    layout->addWidget(tools);
    layout->addWidget(split, 1);
    layout->addWidget(m_message);
    refreshButtons();
}

void SweepPanel::setController(LinkController *controller)
{
    if (m_controller)
        disconnect(m_controller, nullptr, this, nullptr);
    m_controller = controller;
    if (controller) {
        connect(controller, &LinkController::progressChanged, this, &SweepPanel::onProgress);
        connect(controller, &LinkController::pollFinished, this, &SweepPanel::onPollFinished);
        connect(controller, &LinkController::pollingChanged, this, &SweepPanel::onPollingChanged);
    }
    refreshButtons();
}

void SweepPanel::setIntervalsText(const QString &text)
{
    m_intervals->setText(text);
}

void SweepPanel::setCount(int count)
{
    m_count->setValue(count);
}

std::optional<QList<int>> SweepPanel::parseIntervals(const QString &text, QString *error)
{
    if (text.trimmed().isEmpty()) {
        *error = tr("no intervals: write them in milliseconds, separated by commas (100, 200, 300)");
        return std::nullopt;
    }
    QList<int> intervals;
    const QStringList items = text.split(QLatin1Char(','));
    for (qsizetype i = 0; i < items.size(); ++i) {
        const QString item = items.at(i).trimmed();
        if (item.isEmpty()) {
            *error = tr("interval %1 of %2 is empty: write milliseconds between the commas").arg(i + 1).arg(items.size());
            return std::nullopt;
        }
        bool ok = false;
        const int ms = item.toInt(&ok);
        if (!ok || ms < 0 || ms > 3600000) {
            *error = tr("interval %1 ('%2') is not a whole number of milliseconds from 0 to 3600000").arg(i + 1).arg(item);
            return std::nullopt;
        }
        intervals.append(ms);
    }
    return intervals;
}

bool SweepPanel::start()
{
    QString error;
    const std::optional<QList<int>> intervals = parseIntervals(m_intervals->text(), &error);
    if (!intervals) {
        showMessage(tr("Not started: %1").arg(error));
        return false;
    }
    if (!m_controller || !m_controller->isConnected()) {
        showMessage(tr("Not started: connect to a device first"));
        return false;
    }
    if (m_controller->isPolling()) {
        showMessage(tr("Not started: a poll is running; stop it first"));
        return false;
    }
    const QByteArray request = m_requestSource ? m_requestSource() : QByteArray();
    if (request.isEmpty()) {
        showMessage(tr("Not started: there is no request to send (write one in the request composer)"));
        return false;
    }
    if (!m_controller->startSweep(request, *intervals, quint64(m_count->value()))) {
        showMessage(tr("Not started: the link did not take the sweep"));
        return false;
    }
    m_running = true;
    m_intervalCount = int(intervals->size());
    m_model->clear();
    m_progress->setValue(0);
    showMessage(tr("Sweeping %1 intervals, %2 transactions each").arg(intervals->size()).arg(m_count->value()));
    refreshButtons();
    return true;
}

void SweepPanel::stop()
{
    if (m_running && m_controller)
        m_controller->stopPoll();
}

void SweepPanel::onProgress(const EngineProgress &progress)
{
    if (!m_running || progress.runs <= 0)
        return;
    const double planned = double(std::max<quint64>(progress.cyclesPlanned, 1));
    const double done = (double(progress.run) + std::min(1.0, double(progress.cycle) / planned)) / double(progress.runs);
    m_progress->setValue(int(done * 1000));
    showMessage(tr("Interval %1 ms (%2 of %3): cycle %4 of %5")
                    .arg(double(progress.intervalNs) / 1e6, 0, 'g', 6)
                    .arg(progress.run + 1)
                    .arg(progress.runs)
                    .arg(progress.cycle)
                    .arg(progress.cyclesPlanned));
}

void SweepPanel::onPollingChanged(bool polling)
{
    Q_UNUSED(polling);
    refreshButtons();
}

void SweepPanel::onPollFinished(const PollReport &report)
{
    if (!m_running)
        return;
    m_running = false;
    m_progress->setValue(report.stopped ? m_progress->value() : 1000);
    showReport(report);
    showMessage(report.stopped ? tr("Sweep stopped: %1 of %2 intervals run").arg(report.runs.size()).arg(m_intervalCount)
                               : tr("Sweep finished: %1 intervals").arg(report.runs.size()));
    refreshButtons();
    Q_EMIT sweepFinished(report);
}

void SweepPanel::showReport(const PollReport &report)
{
    m_model->setReport(report);
    QList<double> intervals, errorRates, medians, p95s;
    double maxLatency = 0;
    double maxError = 0;
    for (const SweepRow &row : m_model->rows()) {
        const double ms = double(row.intervalNs) / 1e6;
        intervals.append(ms);
        errorRates.append(row.errorRatePercent);
        maxError = std::max(maxError, row.errorRatePercent);
        if (row.answered) {
            medians.append(row.medianMs);
            p95s.append(row.p95Ms);
            maxLatency = std::max(maxLatency, row.p95Ms);
        } else {
            medians.append(qQNaN()); // a gap: nothing was answered at this interval
            p95s.append(qQNaN());
        }
    }
    // The intervals may come in any order; the lines join them by interval.
    m_errorRate->setData(intervals, errorRates);
    m_median->setData(intervals, medians);
    m_p95->setData(intervals, p95s);
    if (!intervals.isEmpty()) {
        const auto [low, high] = std::minmax_element(intervals.cbegin(), intervals.cend());
        const double margin = std::max((*high - *low) * 0.05, 5.0);
        m_plot->xAxis->setRange(*low - margin, *high + margin);
    }
    // Headroom above the highest point keeps the lines clear of the legend in the top corner.
    m_plot->yAxis->setRange(0, std::max(maxError * 1.5, 1.0));
    m_plot->yAxis2->setRange(0, std::max(maxLatency * 1.5, 1.0));
    m_plot->replot();
}

QString SweepPanel::message() const
{
    return m_message->text();
}

void SweepPanel::showMessage(const QString &text)
{
    m_message->setText(text);
}

void SweepPanel::refreshButtons()
{
    m_start->setEnabled(!m_running);
    m_stop->setEnabled(m_running);
    m_intervals->setEnabled(!m_running);
    m_count->setEnabled(!m_running);
}

} // namespace mbscope
