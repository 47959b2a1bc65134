#pragma once

#include <QtWidgets/QMessageBox>
#include <QtWidgets/QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QTimer;

namespace mbscope {

class ReplayController;

// The Replay dock: the opened recording (a capture or a session's traffic) and the ports that
// carry Modbus in it, its offline figures; replay to the connected target at a chosen speed with
// the differences listed and counted; serving its answers on an endpoint. ReplayController does
// the work; this only shows it and asks it.
class ReplayPanel : public QWidget
{
    Q_OBJECT
public:
    // Asked for a capture or session file to open; empty: cancelled.
    using FileChooser = std::function<QString()>;

    // Shown the question asked before a replay whose recording holds writes, answers it: Yes
    // sends them, No (the default button) replays without them, Cancel starts nothing.
    using WritesAsker = std::function<QMessageBox::StandardButton(QMessageBox &question)>;

    explicit ReplayPanel(ReplayController *controller, QWidget *parent = nullptr);

    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    void setWritesAsker(WritesAsker asker) { m_writesAsker = std::move(asker); }

    // The actions behind the buttons (and the Session menu).
    void chooseAndOpen();
    // Opens source with the ports typed in the panel; false (said in the panel) when they are wrong.
    bool open(const QString &source);
    // Asks once when the recording holds writes (how many, to which units and addresses;
    // default No: not sent), then replays.
    void replay();
    void toggleServing();

    // Pacing chosen: 1 as recorded, N times faster, 0 back to back.
    [[nodiscard]] double speed() const;
    [[nodiscard]] QTableView *differencesView() const { return m_table; }
    [[nodiscard]] QString message() const;

private:
    void buildUi();
    void updateState();
    void showMessage(const QString &text, bool problem);

    ReplayController *m_controller;
    FileChooser m_chooser;
    WritesAsker m_writesAsker;
    QLabel *m_source = nullptr;
    QLineEdit *m_mbapPorts = nullptr;
    QLineEdit *m_rtuPorts = nullptr;
    QPushButton *m_openButton = nullptr;
    QLabel *m_analysis = nullptr;
    QComboBox *m_speed = nullptr;
    QPushButton *m_replayButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QLabel *m_counts = nullptr;
    QCheckBox *m_showMatches = nullptr;
    QTableView *m_table = nullptr;
    QLineEdit *m_serveUrl = nullptr;
    QComboBox *m_unrecorded = nullptr;
    QPushButton *m_serveButton = nullptr;
    QLabel *m_serving = nullptr;
    QLabel *m_message = nullptr;
    QTimer *m_servingTimer = nullptr;
};

} // namespace mbscope
