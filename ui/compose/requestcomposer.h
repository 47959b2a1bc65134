#pragma once

#include "protocol/framing.h"
#include "savedrequests.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtWidgets/QWidget>

class QAction;
class QLabel;
class QMenu;
class QMenuBar;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace mbscope {

class RawRequestEditor;
class RequestForm;

// What to send: the Raw tab (the exact bytes) and the Form tab (built from fields) kept in
// sync, then Send once or Poll. The Raw bytes are what leaves: the Form writes its bytes into
// the Raw tab while it is the tab in use, and a Raw request the Form can describe fills the Form.
// Changing the link or unit while on the Raw tab does not rewrite the bytes typed there.
class RequestComposer : public QWidget
{
    Q_OBJECT
public:
    // What a session keeps of the composer: the Raw request, the poll's interval and count, and
    // the named requests. A default State is a new composer's.
    struct State {
        QString requestText;  // the Raw tab's text as typed
        QByteArray request;   // its bytes; empty while the text is not hex (never set by setState)
        int intervalMs = 500; // start to start
        int count = 0;        // 0: until stopped
        QList<SavedRequest> savedRequests;

        friend bool operator==(const State &, const State &) = default;
    };

    explicit RequestComposer(QWidget *parent = nullptr);

    [[nodiscard]] State state() const;
    // Shows state.requestText on the Raw tab (the Form follows when it can describe it) and sets
    // the poll fields. The named requests are shared by every window through QSettings: a list
    // that differs from what is kept there is stored.
    void setState(const State &state);

    [[nodiscard]] RawRequestEditor *rawEditor() const { return m_raw; }
    [[nodiscard]] RequestForm *form() const { return m_form; }
    [[nodiscard]] QTabWidget *tabs() const { return m_tabs; }
    [[nodiscard]] QAction *sendAction() const { return m_sendAction; }
    [[nodiscard]] QAction *pollAction() const { return m_pollAction; }
    [[nodiscard]] QSpinBox *intervalSpin() const { return m_intervalSpin; }
    [[nodiscard]] QSpinBox *countSpin() const { return m_countSpin; }

    // The bytes Send would send (the Raw tab's); empty while they are not hex.
    [[nodiscard]] QByteArray bytes() const;
    void setRequestText(const QString &hex);
    // "Request": Send, Poll, Edit raw bytes (Ctrl+L), Build with the form (Ctrl+B).
    QMenu *addMenu(QMenuBar *menuBar);
    void showRawTab();
    void showFormTab();

    // After a change of link type, while the Raw bytes are a whole frame of the old framing: the
    // same request framed for the new link (what Convert would put in Raw); empty otherwise.
    // Send and Poll wait until the user converts or keeps the bytes as typed.
    [[nodiscard]] QByteArray pendingConversion() const { return m_converted; }
    void acceptConversion();
    void keepAsTyped();
    [[nodiscard]] QWidget *conversionBar() const { return m_conversionBar; }

public Q_SLOTS:
    void setFraming(mbscope::Framing framing);
    void setUnitId(int unit);
    // Whether a link is there to send to (Send and Poll are enabled only then).
    void setLinkReady(bool ready);
    // A listen-only link (the bus monitor): Send and Poll are off, and the hint and their tooltips
    // say why.
    void setListenOnly(bool listenOnly);
    // The window is a tap (the connection bar's Tap): the masters send through it, the composer
    // does not; Send and Poll are off and say why.
    void setTapping(bool tapping);
    void setPolling(bool polling);
    // Sends the current bytes (what Ctrl+Return does).
    void send();
    // Starts a poll, or stops the one running.
    void togglePoll();

Q_SIGNALS:
    void sendRequested(const QByteArray &bytes);
    void pollRequested(const QByteArray &bytes, int intervalMs, quint64 count);
    void stopPollRequested();
    // A Raw request named a unit (the composer's form now uses it): the connection bar follows.
    void unitIdSeen(int unit);
    // The request text, the poll fields or the named requests changed.
    void stateChanged();

private:
    void buildUi();
    void onRawChanged(const QByteArray &bytes, bool valid);
    void onFormChanged();
    void updateActions();
    void offerConversion(Framing from);
    void dismissConversion();

    QTabWidget *m_tabs = nullptr;
    RawRequestEditor *m_raw = nullptr;
    RequestForm *m_form = nullptr;
    QAction *m_sendAction = nullptr;
    QAction *m_pollAction = nullptr;
    QPushButton *m_sendButton = nullptr;
    QPushButton *m_pollButton = nullptr;
    QSpinBox *m_intervalSpin = nullptr;
    QSpinBox *m_countSpin = nullptr;
    QLabel *m_sendHint = nullptr;
    QWidget *m_conversionBar = nullptr;
    QLabel *m_conversionText = nullptr;
    QByteArray m_converted;
    Framing m_framing = Framing::Rtu;
    bool m_syncing = false;
    bool m_linkReady = false;
    bool m_listenOnly = false;
    bool m_tapping = false;
    bool m_polling = false;
};

} // namespace mbscope
