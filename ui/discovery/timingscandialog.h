#pragma once

#include "discovery/timingscanner.h"

#include <QtWidgets/QDialog>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace mbscope {

class Job;
class JobThread;
class TimingResultTree;

// Scan > Timing: how a unit copes with being asked (core/discovery's TimingScanner, reads only):
// how long after connecting it answers, the shortest gap between requests before errors start,
// pipelined MBAP requests, TCP clients at once and the largest read; with the settings that
// follow, copied to the clipboard for a watch link, mbscope's options or Telegraf, and the limits
// measured recorded in a device profile (as mbscope scan --timing UNIT --profile-out FILE does).
class TimingScanDialog : public QDialog
{
    Q_OBJECT
public:
    explicit TimingScanDialog(QWidget *parent = nullptr);
    // Its scanner: the scan dialog hands it the window's recording and shows its frames.
    [[nodiscard]] TimingScanner *scanner() const { return m_scanner; }
    ~TimingScanDialog() override;

    void setTarget(const LinkUrl &url, quint8 unit, quint8 function, quint16 address);
    // The settings the fields make; nullopt, with the reason shown, when they make none.
    [[nodiscard]] std::optional<TimingScanSettings> settings();
    [[nodiscard]] bool isRunning() const;
    // The scan as a job (it runs on a thread of its own).
    [[nodiscard]] Job *job() const { return m_job; }
    [[nodiscard]] const std::optional<TimingReport> &report() const { return m_report; }

public Q_SLOTS:
    // Starts the scan on the dialog's job thread and returns; scanFinished() when it ends.
    void start();
    void stop();
    void copySettings();
    // Merges the limits measured (TimingReport::profileLimits) into the existing profile at path;
    // false, with the reason shown, when it cannot be read or written.
    bool saveLimits(const QString &path);
    void chooseProfileFile();

Q_SIGNALS:
    void scanFinished(bool stopped);

protected:
    void reject() override;

private:
    void updateButtons();
    void onFinished(JobEnd end);

    Job *m_job;
    JobThread *m_jobs;
    TimingScanner *m_scanner; // lives in m_jobs' thread
    TimingResultTree *m_tree;
    QLineEdit *m_target;
    QSpinBox *m_unit;
    QComboBox *m_function;
    QSpinBox *m_address;
    QSpinBox *m_timeout;
    QLineEdit *m_gaps;
    QSpinBox *m_perGap;
    QSpinBox *m_pipeline;
    QSpinBox *m_clients;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_copy;
    QPushButton *m_saveLimits;
    quint8 m_scannedFunction = 3; // the read function of the last scan
    QProgressBar *m_progress;
    QLabel *m_status;
    std::optional<TimingScanSettings> m_runSettings;
    QString m_part; // what the scan measures now: "gap 50 ms"
    std::optional<TimingReport> m_report;
};

} // namespace mbscope
