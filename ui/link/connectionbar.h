#pragma once

#include "pacedialog.h"
#include "tapsetup.h"

#include "transport/linkurl.h"

#include <QtWidgets/QWidget>

#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace mbscope {

class TapFields;
class TlsFilesField;

// Where to talk to: the link type, then host and port (network links) or a serial port with its
// line settings, the unit id and the response timeout. It produces a LinkUrl (url()) and asks
// to connect or disconnect; it never opens anything itself. A target that cannot be used is
// refused in place (errorText()), naming the field and what to change; link failures reported
// later (showError) appear in the same place. Targets that connected are kept as recent targets
// in QSettings ("connection/recent"), TLS files included (tls://host:802?cert=...&key=...&ca=...).
class ConnectionBar : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMaxRecent = 10;

    // What a session keeps of the bar: the target and the timeout.
    struct State {
        std::optional<LinkUrl> target; // the target the fields make (timeout as ?timeout=), if any
        int timeoutMs = 0;             // the timeout field, also when the fields make no target

        friend bool operator==(const State &, const State &) = default;
    };

    explicit ConnectionBar(QWidget *parent = nullptr);

    // The fields as a state. Like url(), a target the fields cannot make is refused in place
    // (errorText()), so a window that follows the state (its session) says at once what is wrong.
    [[nodiscard]] State state();
    // Fills the fields from state.target, with timeoutMs as its timeout when the URL gives none.
    // A state without a target (a session that names none) leaves the fields as they are.
    void setState(const State &state);

    // The target as the fields say, with the timeout as ?timeout=; nullopt with errorText() set.
    [[nodiscard]] std::optional<LinkUrl> url();
    // Fills the fields from a URL (recent target, first run, session). What the fields do not
    // show (rts=, rts_before=, rs485=, turnaround=, mode=listen, busy=, connect=, framing
    // delimiters) is kept and shown beside them (keptOptions()) and goes into url() for as long
    // as the link type stays the same.
    void setUrl(const LinkUrl &url);
    // The kept options in URL form ("rts=up&rts_after=1ms"), empty when none apply.
    [[nodiscard]] QString keptOptions() const;
    // The device's pace on the target (its gap=, warmup=, close=each), set with Recent > Device
    // pace… (PaceDialog)
    // or with the URL set last; kept like the options no field shows, for as long as the link
    // type stays the same.
    [[nodiscard]] PaceDialog::Pace pace() const;
    void setPace(const PaceDialog::Pace &pace);
    [[nodiscard]] QAction *paceAction() const { return m_paceAction; }
    [[nodiscard]] int unitId() const;
    void setUnitId(int unit);
    [[nodiscard]] int timeoutMs() const;
    // The framing of the chosen link type (what "Complete" adds in the composer).
    [[nodiscard]] Framing framing() const;

    // Listen only (the bus monitor): the next connection only listens to a bus another master
    // drives, and never sends. Offered for the links a monitor can listen on (serial, rtu-tcp,
    // ascii-tcp); false for the others whatever the box says.
    [[nodiscard]] bool isListenOnly() const;
    void setListenOnly(bool listenOnly);
    // Tap (the inline tap): the next Connect starts a tap instead, masters connecting to the Tap
    // row's URLs and their requests forwarded to the bar's target (and the row's routes).
    // Listen and Tap exclude each other.
    [[nodiscard]] bool isTap() const;
    void setTap(bool tap);
    // The tap the fields make (TapFields::setup with the bar's target and timeout); nullopt with
    // errorText() set.
    [[nodiscard]] std::optional<TapSetup> tapSetup();
    [[nodiscard]] TapFields *tapFields() const { return m_tapFields; }

    // The controller's view: connected (fields locked, button says Disconnect) or not.
    void setConnected(bool connected);
    [[nodiscard]] bool isConnected() const { return m_connected; }
    void showError(const QString &message);
    // A link that failed after connecting: the link's own words and what the user can do.
    void showLinkFailure(const QString &linkMessage);
    void clearError();
    [[nodiscard]] QString errorText() const;

    void addRecent(const LinkUrl &url);
    [[nodiscard]] QStringList recentTargets() const;
    // Re-reads the serial ports the system has (also done when the list is opened).
    void refreshSerialPorts();

    [[nodiscard]] QPushButton *connectButton() const { return m_connectButton; }
    [[nodiscard]] TlsFilesField *tlsFiles() const { return m_tlsFiles; }

Q_SIGNALS:
    void connectRequested(const mbscope::LinkUrl &url);
    void disconnectRequested();
    // Connect with Listen only ticked: listen to the bus at url, never send.
    void listenRequested(const mbscope::LinkUrl &url);
    // Connect with Tap ticked: start the inline tap.
    void tapRequested(const mbscope::TapSetup &setup);
    void framingChanged(mbscope::Framing framing);
    void unitIdChanged(int unit);
    // Any field changed (the state may differ: a session compares).
    void stateChanged();

private:
    void buildUi();
    void onConnectClicked();
    void onKindChanged();
    void rebuildRecentMenu();
    void editPace();
    void watchFields();
    [[nodiscard]] LinkKind kind() const;

    QComboBox *m_kindCombo = nullptr;
    QWidget *m_networkPage = nullptr; // host and port; shown for network links
    QWidget *m_serialPage = nullptr;  // port and line settings; shown for serial links
    QLineEdit *m_hostEdit = nullptr;
    QSpinBox *m_portSpin = nullptr;
    QComboBox *m_serialPortCombo = nullptr;
    QComboBox *m_baudCombo = nullptr;
    QComboBox *m_parityCombo = nullptr;
    QComboBox *m_dataBitsCombo = nullptr;
    QComboBox *m_stopBitsCombo = nullptr;
    QSpinBox *m_unitSpin = nullptr;
    QSpinBox *m_timeoutSpin = nullptr;
    QCheckBox *m_listenOnlyCheck = nullptr;
    QCheckBox *m_tapCheck = nullptr;
    TapFields *m_tapFields = nullptr; // the Tap row: shown while Tap is ticked
    QPushButton *m_connectButton = nullptr;
    QToolButton *m_recentButton = nullptr;
    QAction *m_paceAction = nullptr;
    QLabel *m_errorLabel = nullptr;
    QLabel *m_keptLabel = nullptr;  // the options of the last URL set that no field shows
    std::optional<LinkUrl> m_kept;  // that URL
    void showKept();
    TlsFilesField *m_tlsFiles = nullptr; // certificate, key and CA of tls:// targets
    LinkKind m_lastKind = LinkKind::Tcp;
    bool m_connected = false;
};

} // namespace mbscope
