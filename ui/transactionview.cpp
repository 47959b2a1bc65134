#include "transactionview.h"

#include "decodepanel.h"
#include "severitystyle.h"

#include "protocol/hextext.h"

#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

QString hexOf(const QByteArray &bytes)
{
    return HexText::format(bytes);
}

// The hex of a frame in the summary line, shortened: the whole frame is in the panel below.
QString shortHex(const QByteArray &bytes)
{
    constexpr int kShown = 16;
    if (bytes.size() <= kShown)
        return hexOf(bytes);
    return hexOf(bytes.first(kShown)) + QStringLiteral(" \u2026");
}

} // namespace

TransactionView::TransactionView(QWidget *parent)
    : QWidget(parent)
    , m_summary(new QLabel(this))
    , m_decode(new DecodePanel(this))
{
    m_summary->setObjectName(QStringLiteral("transactionSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setTextFormat(Qt::RichText);
    m_summary->setContentsMargins(6, 4, 6, 0);
    m_decode->setObjectName(QStringLiteral("answerDecodePanel"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_summary);
    layout->addWidget(m_decode, 1);
    m_refresh.setSingleShot(true);
    connect(&m_refresh, &QTimer::timeout, this, &TransactionView::flush);
    clear();
}

void TransactionView::clear()
{
    m_pending.reset();
    m_shown.reset();
    m_summary->setText(tr("Send a request: its answer appears here, every field explained."));
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
    Severity severity = Severity::Ok;
    switch (t.status) {
    case TransactionStatus::Ok:
    case TransactionStatus::Broadcast: break;
    case TransactionStatus::Exception:
    case TransactionStatus::Late: severity = Severity::Warning; break;
    default: severity = Severity::Error; break;
    }
    const QString colour = severity == Severity::Ok ? QStringLiteral("#1b7f2a") : SeverityStyle::textColor(severity).name();
    QString verdict = transactionStatusName(t.status);
    if (!t.problem.isEmpty() && t.status != TransactionStatus::Ok)
        verdict += QStringLiteral(": ") + t.problem;
    const QString latency = t.latencyNs() >= 0 ? tr("%1 ms").arg(double(t.latencyNs()) / 1e6, 0, 'f', 2) : tr("no answer");
    QString text = tr("<b style=\"color:%1\">%2</b> &nbsp;\u00B7&nbsp; latency <b>%3</b> &nbsp;\u00B7&nbsp; "
                      "request <code>%4</code> (%5 B)")
                       .arg(colour, verdict.toHtmlEscaped(), latency, shortHex(t.request))
                       .arg(t.request.size());
    if (!t.response.isEmpty())
        text += tr(" &rarr; response <code>%1</code> (%2 B)").arg(shortHex(t.response)).arg(t.response.size());
    m_summary->setText(text);

    m_decode->setFraming(framing);
    if (t.response.isEmpty()) {
        m_decode->setRequestText({});
        m_decode->setDirection(Direction::Request);
        m_decode->setFrameText(hexOf(t.request));
    } else {
        m_decode->setRequestText(hexOf(t.request));
        m_decode->setDirection(Direction::Response);
        m_decode->setFrameText(hexOf(t.response));
    }
    m_decode->decodeNow();
    Q_EMIT transactionShown(t);
}

QString TransactionView::summaryText() const
{
    return m_summary->text();
}

} // namespace mbscope
