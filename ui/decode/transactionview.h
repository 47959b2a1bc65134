#pragma once

#include "exchange/transaction.h"
#include "common/frameexchange.h"
#include "protocol/framing.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

#include <optional>

class QLabel;

namespace mbscope {

class DecodeView;

// The answer to what was sent: the DecodeView (request and matched response, each a field tree
// beside its bytes, verdict and latency on top), with the engine's words above it when the
// exchange failed (a refused connection, a timeout). During a poll the newest transaction is shown
// at most kMinRefreshMs apart, so a fast poll does not spend the GUI thread on trees nobody can
// read; a frame picked in the traffic list is shown at once.
class TransactionView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMinRefreshMs = 100;

    explicit TransactionView(QWidget *parent = nullptr);

    void showTransaction(const Transaction &transaction, Framing framing);
    void showExchange(const FrameExchange &exchange);
    // Shows a pending transaction now (tests, and the end of a poll).
    void flush();
    void clear();
    [[nodiscard]] DecodeView *decodeView() const { return m_decode; }
    // The engine's description of a failed exchange; empty after a good one.
    [[nodiscard]] QString problemText() const;
    [[nodiscard]] std::optional<Transaction> shown() const { return m_shown; }

Q_SIGNALS:
    void transactionShown(const mbscope::Transaction &transaction);

private:
    void present(const Transaction &transaction, Framing framing);

    QLabel *m_problem = nullptr;
    DecodeView *m_decode = nullptr;
    QTimer m_refresh;
    QElapsedTimer m_sinceShown;
    std::optional<Transaction> m_pending;
    std::optional<Transaction> m_shown;
    Framing m_pendingFraming = Framing::Auto;
};

} // namespace mbscope
