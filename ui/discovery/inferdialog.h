#pragma once

#include "discovery/registermap.h"
#include "inference/blocksampler.h"
#include "transport/linkurl.h"

#include <QtWidgets/QDialog>

class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace mbscope {

class InferDraftModel;
class Job;
class JobThread;

// Map unit > Infer types: the blocks a map scan found read again and again (core/inference's
// BlockSampler: reads only), then what `mbscope infer` proposes for each value shown as a table to
// confirm or correct row by row (InferDraftModel: every reading side by side with the value it
// gives); "Read again" refreshes those values from the device; the draft, as the person left it,
// is saved as a device profile (InferenceDraft: confirmed rows say so, the rest stay guesses).
// The sampler runs on a JobThread: the window's thread never waits in a loop of its own.
class InferDialog : public QDialog
{
    Q_OBJECT
public:
    explicit InferDialog(QWidget *parent = nullptr);
    ~InferDialog() override;

    // What to sample: the unit at url and the blocks of its map.
    void setSource(const LinkUrl &url, quint8 unit, const RegisterMap &map);
    [[nodiscard]] InferDraftModel *model() const { return m_model; }
    [[nodiscard]] BlockSampler *sampler() const { return m_sampler; } // lives in the job's thread
    [[nodiscard]] Job *job() const { return m_job; }
    [[nodiscard]] bool isRunning() const;
    // Writes the draft as the person left it; false, with the reason shown, when it cannot.
    bool saveProfile(const QString &path);

public Q_SLOTS:
    // Samples and infers in the job's thread; inferred() when done.
    void start();
    // Reads every block once more: the values under every reading.
    void readAgain();
    void stop();

Q_SIGNALS:
    void inferred(int values);
    void readDone();

protected:
    void reject() override;

private:
    enum class Run : quint8 { None, Sample, ReadAgain };

    [[nodiscard]] SampleSettings settings(int samples) const;
    void run(Run what, int samples);
    void onFinished();
    void showInference();
    void chooseFile();
    void updateButtons();

    Job *m_job;
    JobThread *m_jobs;
    BlockSampler *m_sampler; // lives in m_jobs' thread
    InferDraftModel *m_model;
    QTableView *m_table;
    QSpinBox *m_samples;
    QSpinBox *m_interval;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_again;
    QPushButton *m_save;
    QProgressBar *m_progress;
    QLabel *m_source;
    QLabel *m_status;
    LinkUrl m_url;
    quint8 m_unit = 1;
    QList<BlockRequest> m_blocks;
    int m_maxQuantity = 125;
    Run m_run = Run::None;
    QList<BlockSamples> m_read;  // what the last run read, delivered from the job's thread
    bool m_haveDraft = false;
};

} // namespace mbscope
