#include "transactionview.h"

#include "decodeview.h"
#include "common/severitystyle.h"

#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

TransactionView::TransactionView(QWidget *parent)
    : QWidget(parent)
    , m_problem(new QLabel(this))
    , m_decode(new DecodeView(this))
{
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
    layout->addWidget(m_problem);
    layout->addWidget(m_decode, 1);
    m_refresh.setSingleShot(true);
    connect(&m_refresh, &QTimer::timeout, this, &TransactionView::flush);
}

void TransactionView::clear()
{
    m_pending.reset();
    m_shown.reset();
    m_problem->hide();
    m_decode->clear();
}

void TransactionView::showTransaction(const Transaction &transaction, Framing framing)
{
    m_pending = transaction;
    m_pendingFraming = framing;
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
    m_pending.reset();
    m_problem->hide();
    m_decode->showExchange(exchange);
}

void TransactionView::flush()
{
    m_refresh.stop();
    if (!m_pending)
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
