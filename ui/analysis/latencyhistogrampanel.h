#pragma once

#include "latencybinning.h"
#include "latencyruns.h"

#include "exchange/histogram.h"
#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

class QComboBox;
class QCustomPlot;
class QLabel;
class QToolBar;
class QTableView;

namespace mbscope {

class CsvExportAction;
class LatencyStatisticsModel;
class PlotExportMenu;

// The latency histogram of one run (the current poll, the kept reference or an opened capture),
// overall or of one request item, in linear or logarithmic bins, with min, median, p95, p99 and
// max marked, and the run's statistics table beside it.
//
// New transactions only mark the panel stale: it redraws at most every kRedrawMs (a few times a
// second, however many transactions arrive), rebinning the run's stored latencies. The wheel
// zooms, dragging pans; a view moved by hand stays where it is across redraws until "Fit".
class LatencyHistogramPanel : public QWidget
{
    Q_OBJECT

public:
    static constexpr int kRedrawMs = 250;

    explicit LatencyHistogramPanel(LatencyRuns *runs, QWidget *parent = nullptr);

    void setRun(LatencyRuns::Run run);
    [[nodiscard]] LatencyRuns::Run run() const { return m_run; }
    // -1: overall; otherwise a request item's index.
    void setItem(int item);
    [[nodiscard]] int item() const { return m_item; }
    void setScale(LatencyBinning::Scale scale);
    [[nodiscard]] LatencyBinning::Scale scale() const { return m_scale; }

    // Puts the choice of whose latency is shown (LatencySource) first in the tool bar.
    void addSourceChoice(QWidget *choice);
    // Draws now what is pending (tests, screenshots); otherwise within kRedrawMs.
    void redrawNow();
    // Back to the whole histogram after zooming or panning.
    void fitView();

    [[nodiscard]] QCustomPlot *plot() const { return m_plot; }
    [[nodiscard]] LatencyStatisticsModel *statisticsModel() const { return m_model; }
    [[nodiscard]] PlotExportMenu *exportMenu() const { return m_export; }
    [[nodiscard]] CsvExportAction *csvAction() const { return m_csv; }
    // The histogram last drawn.
    [[nodiscard]] const Histogram &histogram() const { return m_histogram; }
    [[nodiscard]] int redrawCount() const { return m_redraws; }

public Q_SLOTS:
    // An opened capture's transactions (ReplayController::captureAnalysed): shown as the Capture run.
    void showTransactions(const QString &title, const QList<mbscope::Transaction> &transactions);

Q_SIGNALS:
    // A plot or table export finished: what was written or why not (for the status bar).
    void exported(const QString &message);

private:
    void scheduleRedraw();
    void redraw();
    void refillRunChoice();
    void refillItemChoice();

    LatencyRuns *m_runs;
    QCustomPlot *m_plot;
    LatencyStatisticsModel *m_model;
    QTableView *m_table;
    PlotExportMenu *m_export;
    CsvExportAction *m_csv;
    QComboBox *m_runChoice;
    QComboBox *m_itemChoice;
    QComboBox *m_scaleChoice;
    QLabel *m_summary;
    QToolBar *m_tools = nullptr;
    QTimer m_redrawTimer;
    Histogram m_histogram;
    LatencyRuns::Run m_run = LatencyRuns::Current;
    int m_item = -1;
    LatencyBinning::Scale m_scale = LatencyBinning::Scale::Linear;
    int m_redraws = 0;
    bool m_viewByHand = false; // zoomed or panned: redraws keep the axes' ranges
    bool m_drawing = false;    // our own range changes are not the user's
};

} // namespace mbscope
