#pragma once

#include "trendseries.h"

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "protocol/readanswer.h"
#include "profile/deviceprofile.h"

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
// says and the legend names them ("temperature, 40209 (degC)"). Zoom, pan, Follow and the cursor
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
    struct Row {
        TrendSeries series;
        QCPGraph *graph = nullptr;
    };

    void addFromFields();
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
    Framing m_framing = Framing::Rtu;
    qint64 m_startNs = 0;
    double m_lastSeconds = 0;
    bool m_filling = false; // the list is being filled: item changes are ours
    bool m_restoring = false;
};

} // namespace mbscope
