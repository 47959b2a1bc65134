#pragma once

#include "profile/simtable.h"
#include "sim/simulatorhost.h"

#include <QtCore/QList>
#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTabWidget;
class QTableView;
class QToolButton;

namespace mbscope {

class SimFaultForm;
class SimRegisterModel;
class SimRunListModel;
class SimScriptPanel;
class SimTrafficModel;

// The simulator at hand: start device profiles (shipped or from a file) on endpoints chosen as a
// URL with a framing choice, several at once, and stop them; the first-run simulator is listed
// too (addRunning). For the simulator picked in the list: each unit's coils and registers live
// and editable (SimRegisterModel: an edit sets the value in the simulator, what clients then
// read), and its fault rules switched while clients poll (SimFaultForm: the next request sees
// them). Below, every simulator's own traffic, bounded (SimTrafficModel), and its scripts' log
// with Reload scripts (SimScriptPanel).
//
// Values and traffic reach the panel in the hosts' batches (SimulatorHost reports at most every
// 100 ms), never one signal per change.
class SimulatorPanel : public QWidget
{
    Q_OBJECT

public:
    explicit SimulatorPanel(QWidget *parent = nullptr);
    ~SimulatorPanel() override; // stops the simulators it started

    // Lists a simulator started elsewhere (not owned; stopping it here stops it).
    void addRunning(SimulatorHost *host, const QString &label, bool builtIn = false);
    // Loads profile (a shipped name or a file) and serves it on url; the new simulator (selected)
    // or nullptr with the reason in message().
    SimulatorHost *startSimulator(const QString &profile, const QString &url);
    void stopSimulator(SimulatorHost *host);
    void selectHost(SimulatorHost *host);
    [[nodiscard]] SimulatorHost *currentHost() const { return m_current; }
    // Shows one unit of the current simulator in the register table.
    void selectUnit(quint8 unit);

    [[nodiscard]] SimRunListModel *runsModel() const { return m_runs; }
    [[nodiscard]] SimRegisterModel *registerModel() const { return m_registers; }
    [[nodiscard]] SimTrafficModel *trafficModel() const { return m_traffic; }
    [[nodiscard]] SimFaultForm *faultForm() const { return m_faults; }
    [[nodiscard]] SimScriptPanel *scriptPanel() const { return m_scripts; }
    [[nodiscard]] QTabWidget *tabs() const { return m_tabs; }
    [[nodiscard]] QString message() const;

private:
    void buildUi();
    void watch(SimulatorHost *host);
    void restoreSavedFaults(SimulatorHost *host);
    void onStartClicked();
    void onFramingChosen();
    void onUrlEdited(const QString &text);
    void chooseProfileFile();
    void showMessage(const QString &text);
    void updateButtons();
    void updateTrafficNote();

    SimRunListModel *m_runs = nullptr;
    SimRegisterModel *m_registers = nullptr;
    SimTrafficModel *m_traffic = nullptr;
    QPointer<SimulatorHost> m_current;
    QList<QPointer<SimulatorHost>> m_owned;

    QComboBox *m_profile = nullptr;
    QToolButton *m_browse = nullptr;
    QComboBox *m_framing = nullptr;
    QLineEdit *m_url = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_message = nullptr;
    QTableView *m_runsView = nullptr;
    QTabWidget *m_tabs = nullptr;
    QComboBox *m_unit = nullptr;
    QTableView *m_registersView = nullptr;
    QLabel *m_editMessage = nullptr;
    SimFaultForm *m_faults = nullptr;
    SimScriptPanel *m_scripts = nullptr;
    QTableView *m_trafficView = nullptr;
    QLabel *m_trafficNote = nullptr;
};

} // namespace mbscope
