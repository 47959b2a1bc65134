#pragma once

#include "trendseries.h"

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "protocol/readanswer.h"
#include "profile/deviceprofile.h"
#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtWidgets/QWidget>

class QAction;
class QComboBox;
class QCPGraph;
class QCustomPlot;
class QLabel;
class QListWidget;
class QListWidgetItem;

namespace mbscope {

class AddressField;
class PlotCursor;
class PlotFollower;
class PlotExportMenu;
class RegisterTable;

// Register trends for the Analysis dock: chosen registers against time, from the answers to the
// reads the window sends (a poll of 03 at 0x0079 gives one point per answer to every chosen
// register it covers); a register ticked later is plotted from the answers already seen. The list on the left holds the profile's registers by name (checked ones
// are plotted) and registers added by address with a format; values are scaled as the profile
// says and the legend names them ("temperature, 40209 (degC)"). Values of the workspace's watches
// are chosen by watch and point name ("plc words \u203a setpoint (rpm)") and plotted from the
// watch runner's samples as the watch decodes them, whatever the bench sends. Zoom, pan, Follow and the cursor
// work as in the LatencyTimePanel.
class RegisterTrendPanel : public QWidget
{
    Q_OBJECT

public:
    static constexpr int kRedrawMs = 50;

    explicit RegisterTrendPanel(QWidget *parent = nullptr);

    // How the transactions' bytes are framed (the connected link's framing).
    void setFraming(Framing framing) { m_framing = framing; }
    // Lists the unit's registers by their profile names (replacing the profile listed before).
    void setProfile(const UnitProfile &unit, const QString &profileName);
    // The register table whose selected cell "Add selected" takes (address, table and format).
    void setRegisterTable(RegisterTable *table);

    // Adds a series to the list (or finds the same register there) and plots it; its index.
    int addSeries(const TrendSeries &series);
    void setSeriesShown(int index, bool shown);
    [[nodiscard]] int seriesCount() const { return int(m_rows.size()); }
    [[nodiscard]] const TrendSeries &series(int index) const { return m_rows.at(index).series; }
    // The graph of a plotted series (nullptr when it was never shown).
    [[nodiscard]] QCPGraph *graphOf(int index) const { return m_rows.at(index).graph; }
    // "Add selected": the register table's current cell as a series; false with a message.
    bool addSelectedFromTable();

    void addTransactions(const QList<Transaction> &transactions);
    void clear();

    // The workspace's watches: their values are offered by watch and point name ("Watch values").
    void setWatches(const SessionWatches &watches);
    // Plots the value at address of watch watchName (its point's name, unit and scaling as the
    // watch decodes it); its index. Chosen series are kept in the settings like the others.
    int addWatchValue(const QString &watchName, quint16 address, const QString &pointName = {});
    // The runner's samples (WatchWorkspace::sampled): one point per answered poll to every chosen
    // value of its watch.
    void addWatchSamples(const QList<mbscope::WatchSample> &samples);
    [[nodiscard]] QComboBox *watchChoice() const { return m_watchChoice; }
    [[nodiscard]] QComboBox *watchValueChoice() const { return m_watchValueChoice; }

    void setFollowing(bool following);
    [[nodiscard]] bool isFollowing() const;
    [[nodiscard]] QCustomPlot *plot() const { return m_plot; }
    [[nodiscard]] PlotCursor *cursor() const { return m_cursor; }
    [[nodiscard]] PlotExportMenu *exportMenu() const { return m_export; }
    [[nodiscard]] QString message() const;
    void redrawNow();

    // How many answers the panel keeps to plot a register ticked later (its history so far).
    static constexpr int kHistoryAnswers = 20000;

private:
    struct Answer {
        double seconds = 0;
        int unitId = 0;
        ReadAnswer read;
    };
    // An answered poll of a watch, kept compact (addresses and scaled values) for the history.
    struct WatchAnswer {
        double seconds = 0;
        QString watchName;
        QList<quint16> addresses;
        QList<double> values;
    };
    struct Row {
        TrendSeries series;
        QCPGraph *graph = nullptr;
    };

    void addFromFields();
    void addFromWatchChoice();
    void refillWatchValues();
    [[nodiscard]] double secondsOf(qint64 ns);
    // The plotted series are kept in the settings and ticked again when listed.
    void saveChoices() const;
    void restoreChoices();
    void onItemChanged(QListWidgetItem *item);
    QCPGraph *graphFor(int index);
    void showMessage(const QString &text);
    void redraw();
    void fitAxes();

    QListWidget *m_list;
    AddressField *m_address;
    QComboBox *m_table;
    QComboBox *m_format;
    QLabel *m_message;
    QCustomPlot *m_plot;
    PlotCursor *m_cursor;
    PlotExportMenu *m_export;
    PlotFollower *m_follower;
    QAction *m_addSelected;
    RegisterTable *m_registerTable = nullptr;
    QList<Row> m_rows;
    QList<Answer> m_history; // the reads answered since the last clear, newest last (bounded)
    QList<WatchAnswer> m_watchHistory; // the watches' answered polls, likewise
    SessionWatches m_watches;
    QComboBox *m_watchChoice;
    QComboBox *m_watchValueChoice;
    Framing m_framing = Framing::Rtu;
    qint64 m_startNs = 0;
    double m_lastSeconds = 0;
    bool m_filling = false; // the list is being filled: item changes are ours
    bool m_restoring = false;
};

} // namespace mbscope
