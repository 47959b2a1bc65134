#pragma once

#include "exchange/transaction.h"
#include "common/frameexchange.h"
#include "protocol/framing.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

#include <optional>

class QLabel;
class QPushButton;

namespace mbscope {

class DecodeView;

// The answer to what was sent: the DecodeView (request and matched response, each a field tree
// beside its bytes, verdict and latency on top), with the engine's words above it when the
// exchange failed (a refused connection, a timeout). During a poll the newest transaction is shown
// at most kMinRefreshMs apart, so a fast poll does not spend the GUI thread on trees nobody can
// read; a frame picked in the traffic list (a click, or Find) is shown at once and stays shown,
// the poll's answers held back, until the user goes back to live (the bar's "Back to live", or a
// new Send or Poll).
class TransactionView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMinRefreshMs = 100;

    explicit TransactionView(QWidget *parent = nullptr);

    // The link's newest transaction: shown when live, else kept for the return to live.
    void showTransaction(const Transaction &transaction, Framing framing);
    // A frame picked in the traffic list: shown, and held until backToLive().
    void showExchange(const FrameExchange &exchange);
    // Shows a pending transaction now (tests, and the end of a poll); nothing while a picked
    // frame is held.
    void flush();
    void clear();
    // Whether the link's transactions are shown as they come (no picked frame held).
    [[nodiscard]] bool isLive() const { return !m_held; }
    // Follows the link again: the newest transaction is shown at once.
    void backToLive();
    [[nodiscard]] QPushButton *backToLiveButton() const { return m_liveButton; }
    [[nodiscard]] DecodeView *decodeView() const { return m_decode; }
    // The engine's description of a failed exchange; empty after a good one.
    [[nodiscard]] QString problemText() const;
    [[nodiscard]] std::optional<Transaction> shown() const { return m_shown; }

Q_SIGNALS:
    void transactionShown(const mbscope::Transaction &transaction);
    // backToLive() let go of a picked frame.
    void wentLive();

private:
    void present(const Transaction &transaction, Framing framing);

    QLabel *m_problem = nullptr;
    QWidget *m_heldBar = nullptr;
    QLabel *m_heldLabel = nullptr;
    QPushButton *m_liveButton = nullptr;
    DecodeView *m_decode = nullptr;
    bool m_held = false;
    QTimer m_refresh;
    QElapsedTimer m_sinceShown;
    std::optional<Transaction> m_pending;
    std::optional<Transaction> m_shown;
    Framing m_pendingFraming = Framing::Auto;
};

} // namespace mbscope
