#pragma once

#include "common/frameexchange.h"
#include "trafficsaver.h"

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"

#include <QtWidgets/QWidget>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableView;
class QToolButton;

namespace mbscope {

class TrafficModel;

// The traffic list of the workbench: every frame in and out, newest at the bottom (followed while
// the view is scrolled to the end), filters by unit, function, direction and verdict, pause,
// clear, find (hex or text) and "Save Traffic As" (all frames or the rows shown, as a journal,
// pcapng, pcap, CSV or JSON lines). Selecting a row emits the frame with its request or answer,
// for the decode view.
class TrafficMonitor : public QWidget
{
    Q_OBJECT

public:
    explicit TrafficMonitor(QWidget *parent = nullptr);

    [[nodiscard]] TrafficModel *model() const { return m_model; }
    [[nodiscard]] QTableView *view() const { return m_view; }

    // "Save Traffic As…": for the File menu; the dock's Save button runs it too.
    [[nodiscard]] QAction *saveAction() const { return m_saveAction; }
    // Saves without asking (saveTrafficAs asks where, what and in which format, then calls it);
    // the outcome is shown in the status line and emitted.
    TrafficSaver::Result saveTo(const QString &path, TrafficFormat format, bool shownOnly);

    [[nodiscard]] bool isPaused() const;
    // The shown row selected, or -1.
    [[nodiscard]] int currentRow() const;
    void selectRow(int row);

public Q_SLOTS:
    void appendFrames(const QList<mbscope::TrafficFrame> &frames);
    void appendTransactions(const QList<mbscope::Transaction> &transactions);
    void appendRecordedTransactions(const QList<mbscope::Transaction> &transactions);
    void appendLinkFrames(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void appendNamedFrames(const QList<mbscope::TrafficFrame> &frames, const QStringList &links);
    void setPaused(bool paused);
    void clear();
    // Puts the cursor in the find field (Ctrl+F in the window).
    void focusSearch();
    void findNext();
    void findPrevious();
    // Asks whether to save all frames or the rows shown (when a filter hides some), then for the
    // file and its format, saves, and shows what was written (with the option Wireshark needs
    // for RTU frames).
    void saveTrafficAs();

Q_SIGNALS:
    void frameSelected(const mbscope::FrameExchange &exchange);
    // A save's outcome, one line (TrafficSaver::Result::summary).
    void saved(const QString &summary, bool ok);

private:
    void buildUi();
    void applyFilter();
    void onCurrentChanged();
    void updateStatus();
    void find(bool forward);
    void onRowsAboutToBeInserted();
    void onRowsInserted();

    TrafficModel *m_model = nullptr;
    QTableView *m_view = nullptr;
    QSpinBox *m_unitSpin = nullptr;
    QComboBox *m_functionCombo = nullptr;
    QComboBox *m_directionCombo = nullptr;
    QComboBox *m_verdictCombo = nullptr;
    QToolButton *m_pauseButton = nullptr;
    QToolButton *m_clearButton = nullptr;
    QAction *m_saveAction = nullptr;
    QString m_lastSaveDirectory;
    QLineEdit *m_searchEdit = nullptr;
    QLabel *m_statusLabel = nullptr;
    QString m_findMessage; // the last find's outcome, shown until the next find or filter
    bool m_follow = true;  // keep the newest row in view: true while the view is at its end
};

} // namespace mbscope
