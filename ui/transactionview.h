#pragma once

#include "engine/transaction.h"
#include "protocol/framing.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

#include <optional>

class QLabel;

namespace mbscope {

class DecodePanel;

// The answer to what was sent: one line with the verdict, the latency and both frames, then the
// decode panel with the response dissected against its matched request (a request that got no
// answer is dissected itself). During a poll the newest transaction is shown at most
// kMinRefreshMs apart, so a fast poll does not spend the GUI thread on trees nobody can read.
class TransactionView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMinRefreshMs = 100;

    explicit TransactionView(QWidget *parent = nullptr);

    void showTransaction(const Transaction &transaction, Framing framing);
    // Shows a pending transaction now (tests, and the end of a poll).
    void flush();
    void clear();
    [[nodiscard]] DecodePanel *decodePanel() const { return m_decode; }
    [[nodiscard]] QString summaryText() const;
    [[nodiscard]] std::optional<Transaction> shown() const { return m_shown; }

Q_SIGNALS:
    void transactionShown(const mbscope::Transaction &transaction);

private:
    void present(const Transaction &transaction, Framing framing);

    QLabel *m_summary = nullptr;
    DecodePanel *m_decode = nullptr;
    QTimer m_refresh;
    QElapsedTimer m_sinceShown;
    std::optional<Transaction> m_pending;
    std::optional<Transaction> m_shown;
    Framing m_pendingFraming = Framing::Auto;
};

} // namespace mbscope
