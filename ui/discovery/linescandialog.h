#pragma once

#include "discovery/linescanner.h"

#include <QtCore/QList>
#include <QtWidgets/QDialog>

#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTreeWidget;

namespace mbscope {

// Scan > Serial settings: tries baud rates, parities and stop bits on a serial port with a known
// read until CRC-valid answers come back (core/discovery's LineScanner, reads only), listing every
// setting tried as it goes. "Use this setting" hands the port with the setting that worked to
// whoever asked (the unit scan's target).
class Job;
class JobThread;

class LineScanDialog : public QDialog
{
    Q_OBJECT
public:
    explicit LineScanDialog(QWidget *parent = nullptr);
    // Its scanner: the scan dialog hands it the window's recording and shows its frames.
    [[nodiscard]] LineScanner *scanner() const { return m_scanner; }
    ~LineScanDialog() override;

    void setTarget(const LinkUrl &url, quint8 function, quint16 address);
    // The settings the fields make; nullopt, with the reason shown, when they make none.
    [[nodiscard]] std::optional<LineScanSettings> settings();
    [[nodiscard]] bool isRunning() const;
    // The scan as a job (it runs on a thread of its own).
    [[nodiscard]] Job *job() const { return m_job; }
    [[nodiscard]] const QList<LineTrial> &trials() const { return m_trials; }
    // The port with the selected working setting (the first that worked without a selection).
    [[nodiscard]] std::optional<LinkUrl> workingUrl() const;

public Q_SLOTS:
    // Starts the scan on the dialog's job thread and returns; scanFinished() when it ends.
    void start();
    void stop();

Q_SIGNALS:
    void settingChosen(const mbscope::LinkUrl &url);
    void scanFinished(mbscope::JobEnd end);

protected:
    void reject() override;

private:
    void onTried(const LineTrial &trial);
    void summarise(JobEnd end);
    void updateButtons();
    void onFinished(JobEnd end);

    Job *m_job;
    JobThread *m_jobs;
    LineScanner *m_scanner; // lives in m_jobs' thread
    QTreeWidget *m_list;
    QLineEdit *m_target;
    QLineEdit *m_bauds;
    QList<QCheckBox *> m_parities; // E, N, O
    QList<QCheckBox *> m_stopBits; // 1, 2
    QLineEdit *m_units;
    QSpinBox *m_timeout;
    QCheckBox *m_first;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_use;
    QProgressBar *m_progress;
    QLabel *m_status;
    LineScanSettings m_ran;
    QList<LineTrial> m_trials;
};

} // namespace mbscope
