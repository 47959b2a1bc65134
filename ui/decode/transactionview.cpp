#include "transactionview.h"

#include "decodeview.h"
#include "common/severitystyle.h"

#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

TransactionView::TransactionView(QWidget *parent)
    : QWidget(parent)
    , m_problem(new QLabel(this))
    , m_heldBar(new QWidget(this))
    , m_heldLabel(new QLabel(m_heldBar))
    , m_liveButton(new QPushButton(tr("Back to live"), m_heldBar))
    , m_decode(new DecodeView(this))
{
    // Shown while a frame picked in the traffic list is held: what is shown, and the way back.
    m_heldBar->setObjectName(QStringLiteral("answerHeldBar"));
    m_heldLabel->setObjectName(QStringLiteral("answerHeldLabel"));
    m_heldLabel->setWordWrap(true);
    m_liveButton->setObjectName(QStringLiteral("answerBackToLive"));
    m_liveButton->setToolTip(tr("Show the link's answers as they come again"));
    auto *heldLayout = new QHBoxLayout(m_heldBar);
    heldLayout->setContentsMargins(6, 4, 6, 0);
    heldLayout->addWidget(m_heldLabel, 1);
    heldLayout->addWidget(m_liveButton);
    m_heldBar->hide();
    connect(m_liveButton, &QPushButton::clicked, this, &TransactionView::backToLive);
    m_problem->setObjectName(QStringLiteral("transactionProblem"));
    m_problem->setWordWrap(true);
    m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->setContentsMargins(6, 4, 6, 0);
    QPalette p = m_problem->palette();
    p.setColor(QPalette::WindowText, SeverityStyle::textColor(Severity::Error));
    m_problem->setPalette(p);
    m_problem->hide();
    m_decode->setObjectName(QStringLiteral("answerDecodeView"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_heldBar);
    layout->addWidget(m_problem);
    layout->addWidget(m_decode, 1);
    m_refresh.setSingleShot(true);
    connect(&m_refresh, &QTimer::timeout, this, &TransactionView::flush);
}

void TransactionView::clear()
{
    m_held = false;
    m_heldBar->hide();
    m_pending.reset();
    m_shown.reset();
    m_problem->hide();
    m_decode->clear();
}

void TransactionView::showTransaction(const Transaction &transaction, Framing framing)
{
    m_pending = transaction;
    m_pendingFraming = framing;
    if (m_held)
        return; // shown when the user goes back to live
    if (!m_sinceShown.isValid() || m_sinceShown.elapsed() >= kMinRefreshMs) {
        flush();
        return;
    }
    if (!m_refresh.isActive())
        m_refresh.start(int(kMinRefreshMs - m_sinceShown.elapsed()));
}

void TransactionView::showExchange(const FrameExchange &exchange)
{
    m_refresh.stop();
    m_held = true;
    m_heldLabel->setText(exchange.transactionId != 0
                             ? tr("Showing transaction %1, picked in the traffic list: the link's new answers are not shown.")
                                   .arg(exchange.transactionId)
                             : tr("Showing a frame picked in the traffic list: the link's new answers are not shown."));
    m_heldBar->show();
    m_problem->hide();
    m_decode->showExchange(exchange);
}

void TransactionView::backToLive()
{
    if (!m_held)
        return;
    m_held = false;
    m_heldBar->hide();
    m_sinceShown.invalidate();
    if (m_pending)
        flush();
    else if (m_shown)
        present(*m_shown, m_pendingFraming);
    else
        m_decode->clear();
    Q_EMIT wentLive();
}

void TransactionView::flush()
{
    m_refresh.stop();
    if (m_held || !m_pending)
        return;
    const Transaction transaction = *std::exchange(m_pending, std::nullopt);
    present(transaction, m_pendingFraming);
}

void TransactionView::present(const Transaction &t, Framing framing)
{
    m_sinceShown.start();
    m_shown = t;
    const bool failed = t.status != TransactionStatus::Ok && t.status != TransactionStatus::Broadcast;
    m_problem->setText(failed && !t.problem.isEmpty()
                           ? tr("%1: %2").arg(transactionStatusName(t.status), t.problem)
                           : QString());
    m_problem->setVisible(!m_problem->text().isEmpty());
    m_decode->showTransaction(t, framing);
    Q_EMIT transactionShown(t);
}

QString TransactionView::problemText() const
{
    return m_problem->isVisibleTo(this) ? m_problem->text() : QString();
}

} // namespace mbscope
