#pragma once

#include "engine/engineprogress.h"
#include "engine/pollreport.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtWidgets/QWidget>

#include <functional>
#include <optional>

class QCPGraph;
class QCustomPlot;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace mbscope {

class LinkController;
class PlotExportMenu;
class SweepTableModel;

// The Sweep panel of the Analysis dock: polls the composer's request count times at each
// interval of a list ("100, 200, 300, 333, 350, 400" ms), one interval after the other, through
// the LinkController's engine (TransactionEngine::startSweep), and shows what the interval does
// to the device: error rate (%) on the left axis, median and p95 latency (ms) on the right one,
// against the interval, with the table of every figure beside the plot. Plot and table export.
class SweepPanel : public QWidget
{
    Q_OBJECT

public:
    explicit SweepPanel(QWidget *parent = nullptr);

    void setController(LinkController *controller);
    // Where Start takes the request bytes from (the composer's Raw bytes, as Send does).
    void setRequestSource(std::function<QByteArray()> source) { m_requestSource = std::move(source); }

    void setIntervalsText(const QString &text);
    void setCount(int count);
    // The intervals in ms, or nullopt with error saying which item is wrong and why.
    [[nodiscard]] static std::optional<QList<int>> parseIntervals(const QString &text, QString *error);

    // Starts the sweep; false with message() saying why not.
    bool start();
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }
    // Shows a finished sweep (also one run elsewhere): table and plot.
    void showReport(const PollReport &report);

    [[nodiscard]] SweepTableModel *model() const { return m_model; }
    [[nodiscard]] QCustomPlot *plot() const { return m_plot; }
    [[nodiscard]] QCPGraph *errorRateGraph() const { return m_errorRate; }
    [[nodiscard]] QCPGraph *medianGraph() const { return m_median; }
    [[nodiscard]] QCPGraph *p95Graph() const { return m_p95; }
    [[nodiscard]] PlotExportMenu *exportMenu() const { return m_export; }
    [[nodiscard]] QString message() const;

Q_SIGNALS:
    void sweepFinished(const mbscope::PollReport &report);

private:
    void onProgress(const EngineProgress &progress);
    void onPollFinished(const PollReport &report);
    void onPollingChanged(bool polling);
    void showMessage(const QString &text);
    void refreshButtons();

    LinkController *m_controller = nullptr;
    std::function<QByteArray()> m_requestSource;
    QLineEdit *m_intervals;
    QSpinBox *m_count;
    QPushButton *m_start;
    QPushButton *m_stop;
    QProgressBar *m_progress;
    QLabel *m_message;
    QCustomPlot *m_plot;
    QCPGraph *m_errorRate;
    QCPGraph *m_median;
    QCPGraph *m_p95;
    PlotExportMenu *m_export;
    SweepTableModel *m_model;
    QTableView *m_table;
    bool m_running = false;
    int m_intervalCount = 0;
};

} // namespace mbscope
