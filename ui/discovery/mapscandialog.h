#pragma once

#include "discovery/mapscansettings.h"
#include "discovery/registermap.h"
#include "job/jobend.h"
#include "job/jobprogress.h"

#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtWidgets/QDialog>

#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace mbscope {

class InferDialog;
class Job;
class JobThread;
class MapResultTree;
class MapScanner;

// Scan > Map unit: which addresses of each table a unit has, the largest read each function takes
// and which optional functions it answers (core/discovery's MapScanner: reads only, bounded by a
// request count), shown as a tree. The map becomes a device profile draft that `mbscope simulate
// --profile` serves ("Save profile draft"), or a watch per block (watchesRequested()), or goes on to
// Infer types (InferDialog: what each value of the blocks is, confirmed row by row).
class MapScanDialog : public QDialog
{
    Q_OBJECT
public:
    explicit MapScanDialog(QWidget *parent = nullptr);
    // Its scanner: the scan dialog hands it the window's recording and shows its frames.
    [[nodiscard]] MapScanner *scanner() const { return m_scanner; }
    ~MapScanDialog() override;

    void setTarget(const LinkUrl &url, quint8 unit);
    // The settings the fields make; nullopt, with the reason shown, when they make none.
    [[nodiscard]] std::optional<MapScanSettings> settings();
    [[nodiscard]] bool isRunning() const;
    // The scan as a job: its state, progress and end (the scan itself runs on a thread of its own).
    [[nodiscard]] Job *job() const { return m_job; }
    [[nodiscard]] const std::optional<RegisterMap> &map() const { return m_map; }
    [[nodiscard]] QList<WatchDefinition> watches() const;
    // Writes the map as a profile draft to path; false, with the reason shown, when it cannot.
    bool saveDraft(const QString &path);
    // Infer types: the dialog that samples the map's blocks and proposes what each value is,
    // made on the first call and set to this map's unit.
    InferDialog *inferTypes();

public Q_SLOTS:
    // Starts the scan on the dialog's job thread and returns; scanFinished() when it ends.
    void start();
    void stop();

Q_SIGNALS:
    void watchesRequested(const QList<mbscope::WatchDefinition> &watches);
    void scanFinished(mbscope::JobEnd end);

protected:
    void reject() override;

private:
    void onProgress(const JobProgress &progress);
    void onFinished(JobEnd end);
    void chooseDraftFile();
    void updateButtons();

    Job *m_job;
    JobThread *m_jobs;
    MapScanner *m_scanner; // lives in m_jobs' thread
    MapResultTree *m_tree;
    QLineEdit *m_target;
    QSpinBox *m_unit;
    QSpinBox *m_first;
    QSpinBox *m_last;
    QSpinBox *m_step;
    QList<QCheckBox *> m_tables; // 01-04
    QCheckBox *m_optional;
    QSpinBox *m_timeout;
    QSpinBox *m_gap;
    QSpinBox *m_maxRequests;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_save;
    QPushButton *m_add;
    QPushButton *m_infer;
    InferDialog *m_inferDialog = nullptr;
    QProgressBar *m_progress;
    QLabel *m_status;
    std::optional<MapScanSettings> m_runSettings;
    std::optional<RegisterMap> m_map;
    QString m_mapTarget;
    LinkUrl m_mapUrl;
};

} // namespace mbscope
