#pragma once

#include "conformance/conformanceresult.h"
#include "conformance/conformancesettings.h"
#include "exchange/trafficentry.h"
#include "transport/linkurl.h"

#include <QtWidgets/QDialog>

#include <memory>
#include <optional>

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace mbscope {

class ConformanceResultModel;
class ConformanceRunner;
class Job;
class JobThread;
class TrafficLog;

// Tools > Conformance: the battery of `mbscope conform` (core/conformance's ConformanceRunner)
// against the window's link, a row per check as it is decided, a progress bar, Stop, and the
// scorecard saved as HTML, PDF, JSON or JUnit XML. Reads only unless Writable names addresses, as
// --writable does on the command line.
class ConformanceDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ConformanceDialog(QWidget *parent = nullptr);
    ~ConformanceDialog() override;

    void setTarget(const LinkUrl &url);
    // The settings the fields make; nullopt, with what is wrong shown in the status line.
    [[nodiscard]] std::optional<ConformanceSettings> settings();
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] ConformanceResultModel *model() const { return m_model; }
    [[nodiscard]] const std::optional<ConformanceResult> &result() const { return m_result; }
    // The scorecard to path, in the format its suffix names (.html or .htm, .pdf, .json, .xml for
    // JUnit); false with *error when there is none yet, the suffix is unknown or the file cannot be written.
    bool saveReport(const QString &path, QString *error = nullptr);
    // The log a run's frames are recorded into too (the window's recording of its link); null:
    // none. Taken by the next run.
    void setTrafficLog(TrafficLog *log) { m_trafficLog = log; }

public Q_SLOTS:
    // Starts the battery (from the event loop: the call returns at once; finished() follows).
    void start();
    void stop();
    void save();

Q_SIGNALS:
    void checkDecided(int done, int total);
    void finished(bool passed);
    // Every frame of a run in and out (the window's traffic list takes them, as a scan's).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

protected:
    void reject() override;

private:
    void run(const ConformanceSettings &settings);
    void onFinished();
    void updateButtons();

    ConformanceResultModel *m_model;
    QLineEdit *m_target;
    QSpinBox *m_unit;
    QSpinBox *m_timeout;
    QLineEdit *m_profile;
    QLineEdit *m_writable;
    QLineEdit *m_only;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_save;
    QProgressBar *m_progress;
    QLabel *m_status;
    QTableView *m_table;
    Job *m_job;
    JobThread *m_jobs;  // the battery runs in its thread: the window's never nests a loop
    std::unique_ptr<ConformanceRunner> m_runner; // made here, run there, dropped here when done
    std::optional<ConformanceResult> m_delivered; // the run's scorecard, from the job's thread
    TrafficLog *m_trafficLog = nullptr;
    std::optional<ConformanceResult> m_result;
};

} // namespace mbscope
