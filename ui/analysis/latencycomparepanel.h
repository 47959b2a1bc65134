#pragma once

#include "latencybinning.h"
#include "latencyruns.h"

#include "exchange/histogram.h"

#include <QtCore/QList>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

class QComboBox;
class QCustomPlot;
class QTableView;

namespace mbscope {

class CsvExportAction;
class LatencyStatisticsModel;
class PlotExportMenu;

// Two latency histograms overlaid on common bins, with a legend and their statistics side by
// side: two request items of one run, the current poll against a kept reference, or an opened
// capture (the recorded run) against the current poll (the replayed one). Each side is a run and
// an item (or overall). Redraws batched as in LatencyHistogramPanel.
class LatencyComparePanel : public QWidget
{
    Q_OBJECT

public:
    static constexpr int kRedrawMs = 250;

    // What one side shows.
    struct Side {
        LatencyRuns::Run run = LatencyRuns::Current;
        int item = -1; // -1: overall
        friend bool operator==(const Side &, const Side &) = default;
    };

    explicit LatencyComparePanel(LatencyRuns *runs, QWidget *parent = nullptr);

    void setSides(Side first, Side second);
    [[nodiscard]] Side first() const { return m_sides[0]; }
    [[nodiscard]] Side second() const { return m_sides[1]; }
    void setScale(LatencyBinning::Scale scale);
    [[nodiscard]] LatencyBinning::Scale scale() const { return m_scale; }
    void redrawNow();

    [[nodiscard]] QCustomPlot *plot() const { return m_plot; }
    [[nodiscard]] LatencyStatisticsModel *statisticsModel() const { return m_model; }
    [[nodiscard]] PlotExportMenu *exportMenu() const { return m_export; }
    [[nodiscard]] CsvExportAction *csvAction() const { return m_csv; }
    // The two histograms last drawn, on the same bins.
    [[nodiscard]] const QList<Histogram> &histograms() const { return m_histograms; }

Q_SIGNALS:
    void exported(const QString &message);

private:
    void scheduleRedraw();
    void redraw();
    void refillChoices();
    [[nodiscard]] QString sideTitle(const Side &side) const;

    LatencyRuns *m_runs;
    QCustomPlot *m_plot;
    LatencyStatisticsModel *m_model;
    QTableView *m_table;
    PlotExportMenu *m_export;
    CsvExportAction *m_csv;
    QComboBox *m_choices[2];
    QComboBox *m_scaleChoice;
    QTimer m_redrawTimer;
    QList<Histogram> m_histograms;
    Side m_sides[2] = {{LatencyRuns::Current, -1}, {LatencyRuns::Current, 0}};
    LatencyBinning::Scale m_scale = LatencyBinning::Scale::Linear;
};

} // namespace mbscope
