#pragma once

#include "job/jobend.h"
#include "job/jobprogress.h"
#include "exchange/trafficentry.h"
#include "discovery/unitscansettings.h"

#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtWidgets/QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace mbscope {

class LineScanDialog;
class MapScanDialog;
class TimingScanDialog;
class ScanResultModel;
class ProbeChannel;
class TrafficLog;
class UnitScanner;

// Tools > Scan: asks every unit id of a range the same harmless read (core/discovery's
// UnitScanner, with an engine of its own: the window's connection is left alone) and lists what
// each did, with a progress bar, the time left and Stop. Found units become watches: "Copy as
// watches (JSON)" puts them on the clipboard, and watchesRequested() hands them to whoever shows
// watches (the window's workspace).
class ScanDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ScanDialog(QWidget *parent = nullptr);
    ~ScanDialog() override;

    // The link to scan (the window's current target); the text field can change it.
    void setTarget(const LinkUrl &url);
    // The settings the fields make; nullopt, with the reason shown, when they make none.
    [[nodiscard]] std::optional<UnitScanSettings> settings();
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] ScanResultModel *model() const { return m_model; }
    // Watches of the selected found units, or of every found unit when none is selected.
    [[nodiscard]] QList<WatchDefinition> watches() const;
    // The window's recording (LinkController::trafficLog, shared): every scan's frames, this
    // dialog's and those of the map, timing and line dialogs it opens, go there; nullptr: none.
    void setTrafficLog(TrafficLog *log);

public Q_SLOTS:
    void start();
    void stop();
    void copyWatches();
    // Record in profile...: the units that answered, and what the others got, merged into a
    // profile file the user picks (ProfileDraft::mergeUnits, as scan --units --profile-out).
    void recordUnits();
    // Opens Map a unit's registers on the selected found unit (the first found without a selection).
    MapScanDialog *mapSelectedUnit();
    // Opens Time a unit on the selected found unit (the first found without a selection), asking
    // the read the scan asked.
    TimingScanDialog *timeSelectedUnit();
    // Opens Find a serial line's settings on the target (a serial port); the setting chosen there
    // becomes the target.
    LineScanDialog *findLineSettings();

Q_SIGNALS:
    void watchesRequested(const QList<mbscope::WatchDefinition> &watches);
    void scanFinished(mbscope::JobEnd end);
    // Every frame a scan sends and gets, as its engine logs it (the window's traffic view).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

protected:
    void reject() override;

private:
    void onProgress(const JobProgress &progress);
    void onFinished(JobEnd end);
    void updateButtons();
    // A scanner's channel: on the recording, its frames shown.
    void adopt(ProbeChannel *channel);

    UnitScanner *m_scanner;
    TrafficLog *m_trafficLog = nullptr;
    ScanResultModel *m_model;
    QLineEdit *m_target;
    QSpinBox *m_first;
    QSpinBox *m_last;
    QComboBox *m_function;
    QSpinBox *m_address;
    QSpinBox *m_quantity;
    QSpinBox *m_timeout;
    QSpinBox *m_gap;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_copy;
    QPushButton *m_add;
    QPushButton *m_map;
    QPushButton *m_timing;
    QPushButton *m_line;
    QPushButton *m_recordUnits;
    LineScanDialog *m_lineDialog = nullptr;
    MapScanDialog *m_mapDialog = nullptr;
    TimingScanDialog *m_timingDialog = nullptr;
    [[nodiscard]] int chosenFoundRow() const;
    QProgressBar *m_progress;
    QLabel *m_status;
    QTableView *m_table;
    UnitScanSettings m_running;
};

} // namespace mbscope
