#include "decodeview.h"

#include "dissectionsummary.h"
#include "common/exchangeformat.h"
#include "frameinspector.h"
#include "common/severitystyle.h"
#include "common/trafficstyle.h"

#include "protocol/dissector.h"

#include <QtCore/QJsonDocument>
#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenu>
#include <QtGui/QResizeEvent>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

DecodeView::DecodeView(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    clear();
}

void DecodeView::buildUi()
{
    m_header = new QLabel(this);
    m_header->setObjectName(QStringLiteral("exchangeHeader"));
    m_header->setWordWrap(true);
    m_header->setTextFormat(Qt::RichText);
    m_header->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_copyButton = new QToolButton(this);
    m_copyButton->setObjectName(QStringLiteral("copyButton"));
    m_copyButton->setText(tr("Copy"));
    m_copyButton->setToolTip(tr("Copy both frames: as text (as `mbscope decode` prints them), as JSON or as hex"));
    m_copyButton->setPopupMode(QToolButton::MenuButtonPopup);
    auto *menu = new QMenu(m_copyButton);
    const auto addCopy = [this, menu](const QString &text, CopyFormat format) {
        QAction *action = menu->addAction(text);
        action->setObjectName(QStringLiteral("copyAs") + QString::number(int(format)));
        connect(action, &QAction::triggered, this, [this, format] { copy(format); });
        return action;
    };
    addCopy(tr("Copy as &text"), CopyFormat::Text);
    addCopy(tr("Copy as &JSON"), CopyFormat::Json);
    addCopy(tr("Copy as &hex"), CopyFormat::Hex);
    m_copyButton->setMenu(menu);
    connect(m_copyButton, &QToolButton::clicked, this, [this] { copy(CopyFormat::Text); });

    auto *top = new QHBoxLayout;
    top->addWidget(m_header, 1);
    top->addWidget(m_copyButton, 0, Qt::AlignTop);

    m_request = new FrameInspector(this);
    m_request->setObjectName(QStringLiteral("requestInspector"));
    m_response = new FrameInspector(this);
    m_response->setObjectName(QStringLiteral("responseInspector"));
    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->addWidget(m_request);
    m_splitter->addWidget(m_response);
    m_splitter->setChildrenCollapsible(false);
    connect(m_splitter, &QSplitter::splitterMoved, this, [this] { m_splitterMoved = true; });

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_splitter, 1);
}

void DecodeView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    fitSplitter();
}

// An answer has more fields than its request (a read returns the values asked for): the
// response gets two thirds of the height, the request a third, until the user moves the handle.
// Left to its size hints the splitter halves the room, and a 720 px window then showed six
// rows of the answer's fields.
void DecodeView::fitSplitter()
{
    const int total = m_splitter->height() - m_splitter->handleWidth();
    if (m_splitterMoved || total <= 0)
        return;
    const int request = qMax(m_request->minimumSizeHint().height(), total / 3);
    m_splitter->setSizes({request, qMax(0, total - request)});
}

const Dissection &DecodeView::requestDissection() const
{
    return m_request->dissection();
}

const Dissection &DecodeView::responseDissection() const
{
    return m_response->dissection();
}

void DecodeView::showExchange(const FrameExchange &exchange)
{
    m_exchange = exchange;
    DissectOptions options;
    options.framing = exchange.framing;
    if (exchange.hasRequest()) {
        options.direction = Direction::Request;
        m_request->setDissection(Dissector::dissect(exchange.request, options));
    } else {
        m_request->setPlaceholder(exchange.selected == TrafficDirection::In
                                      ? tr("No request: this frame answers none that was sent (%1)")
                                            .arg(TrafficStyle::verdictText(exchange.verdict))
                                      : tr("No request"));
    }
    if (exchange.hasResponse()) {
        // An answer is checked against its request (byte count, echoes, transaction id); without
        // one its direction is read from the bytes.
        options.direction = exchange.hasRequest() ? Direction::Response : Direction::Auto;
        options.request = exchange.request;
        m_response->setDissection(Dissector::dissect(exchange.response, options));
    } else if (exchange.verdict == TrafficVerdict::Sent) {
        m_response->setPlaceholder(tr("No answer yet"));
    } else if (exchange.verdict == TrafficVerdict::Broadcast) {
        m_response->setPlaceholder(tr("Broadcast: no answer is expected"));
    } else {
        m_response->setPlaceholder(tr("No answer: %1").arg(TrafficStyle::verdictText(exchange.verdict)));
    }
    updateHeader();
    Q_EMIT shown();
}

void DecodeView::showTransaction(const Transaction &transaction, Framing framing)
{
    FrameExchange exchange;
    exchange.request = transaction.request;
    exchange.response = transaction.response;
    exchange.framing = framing;
    exchange.verdict = trafficVerdict(transaction.status);
    exchange.latencyNs = transaction.latencyNs();
    exchange.latencyToEnd = true;
    exchange.transactionId = transaction.id;
    exchange.selected = transaction.response.isEmpty() ? TrafficDirection::Out : TrafficDirection::In;
    showExchange(exchange);
}

void DecodeView::clear()
{
    m_exchange = {};
    m_request->setTitle(tr("Request"));
    m_response->setTitle(tr("Response"));
    m_request->setPlaceholder(tr("Select a frame in the traffic list, or send a request"));
    m_response->setPlaceholder({});
    m_header->setText(tr("No exchange selected"));
    Q_EMIT shown();
}

void DecodeView::updateHeader()
{
    const FrameExchange &e = m_exchange;
    const QString latency = ExchangeFormat::latencyText(e.latencyNs);
    const QString mark = QStringLiteral(" \u25C0"); // the frame picked in the traffic list
    m_request->setTitle(tr("Request") + (e.selected == TrafficDirection::Out ? mark : QString()));
    QString responseTitle = tr("Response");
    if (!latency.isEmpty())
        responseTitle += QStringLiteral(" \u00B7 ") + tr("after %1").arg(latency);
    m_response->setTitle(responseTitle + (e.selected == TrafficDirection::In ? mark : QString()));

    const Dissection &main = e.hasRequest() ? requestDissection() : responseDissection();
    QStringList parts;
    const Severity severity = TrafficStyle::severity(e.verdict);
    // "ok" in the palette's text colour, named nowhere: a colour written into the HTML would stay
    // when the theme changes (black on dark grey).
    const QString verdict = TrafficStyle::verdictText(e.verdict).toHtmlEscaped();
    parts << (severity == Severity::Ok ? QStringLiteral("<b>%1</b>").arg(verdict)
                                       : QStringLiteral("<b style=\"color:%1\">%2</b>").arg(SeverityStyle::textColor(severity).name(), verdict));
    if (!main.fields.isEmpty())
        parts << DissectionSummary::text(main).toHtmlEscaped();
    // Two measures of latency exist (the traffic list's and the Analysis dock's): the header
    // says which one it shows, so that two figures for one exchange never silently disagree.
    if (!latency.isEmpty())
        parts << (e.latencyToEnd ? tr("latency %1 to the answer's last byte") : tr("latency %1 to the answer's first byte"))
                     .arg(latency);
    if (e.transactionId != 0)
        parts << tr("transaction %1").arg(e.transactionId);
    if (!e.link.isEmpty())
        parts << e.link.toHtmlEscaped();
    m_header->setText(parts.join(QStringLiteral(" \u00B7 ")));
    m_header->setToolTip(latency.isEmpty() ? QString()
                         : e.latencyToEnd
                             ? tr("Latency of the transaction, as the Analysis dock and the poll's figures count it: from the "
                                  "request sent (on a serial line, its last byte on the line) to the answer's last byte. The "
                                  "traffic list's Latency column measures to the answer's first byte.")
                             : tr("Latency as the traffic list shows it: from the request's write to the answer's first "
                                  "byte. The Analysis dock measures to the answer's last byte."));
}

QString DecodeView::copyText(CopyFormat format) const
{
    ExchangeFormat::Exchange e;
    e.request = &requestDissection();
    e.response = &responseDissection();
    e.latencyNs = m_exchange.latencyNs;
    if (m_exchange.hasRequest() || m_exchange.hasResponse())
        e.verdict = QLatin1String(trafficVerdictName(m_exchange.verdict));
    switch (format) {
    case CopyFormat::Text:
        return ExchangeFormat::toText(e);
    case CopyFormat::Json:
        return QString::fromUtf8(QJsonDocument(ExchangeFormat::toJson(e)).toJson(QJsonDocument::Indented));
    case CopyFormat::Hex:
        return ExchangeFormat::toHex(e);
    }
    return {};
}

void DecodeView::copy(CopyFormat format)
{
    QGuiApplication::clipboard()->setText(copyText(format));
}

} // namespace mbscope
