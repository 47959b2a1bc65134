#include "requestcomposer.h"

#include "rawrequesteditor.h"
#include "requestform.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"

#include <QtCore/QAbstractItemModel>
#include <QtGui/QAction>
#include <QtGui/QKeySequence>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

RequestComposer::RequestComposer(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    updateActions();
}

void RequestComposer::buildUi()
{
    m_raw = new RawRequestEditor(this);
    m_raw->setObjectName(QStringLiteral("rawRequestEditor"));
    m_form = new RequestForm(this);
    m_form->setObjectName(QStringLiteral("requestForm"));
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("composerTabs"));
    m_tabs->addTab(m_raw, tr("&Raw"));
    m_tabs->addTab(m_form, tr("F&orm"));

    // Ctrl+Return sends from anywhere in the composer, the hex editor included.
    m_sendAction = new QAction(tr("&Send"), this);
    m_sendAction->setObjectName(QStringLiteral("sendAction"));
    m_sendAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    m_sendAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_sendAction->setToolTip(tr("Send the request once (Ctrl+Return)"));
    addAction(m_sendAction);
    connect(m_sendAction, &QAction::triggered, this, &RequestComposer::send);
    m_pollAction = new QAction(tr("Start &poll"), this);
    m_pollAction->setObjectName(QStringLiteral("pollAction"));
    m_pollAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Return));
    m_pollAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(m_pollAction);
    connect(m_pollAction, &QAction::triggered, this, &RequestComposer::togglePoll);

    m_sendButton = new QPushButton(tr("&Send"), this);
    m_sendButton->setObjectName(QStringLiteral("sendButton"));
    m_sendButton->setToolTip(tr("Send the request once (Ctrl+Return)"));
    QFont bold = m_sendButton->font();
    bold.setBold(true);
    m_sendButton->setFont(bold);
    m_sendButton->setMinimumWidth(m_sendButton->fontMetrics().horizontalAdvance(QStringLiteral("Send  (Ctrl+Return)")));
    m_sendButton->setText(tr("&Send  (Ctrl+Return)"));
    connect(m_sendButton, &QPushButton::clicked, this, &RequestComposer::send);
    m_sendHint = new QLabel(this);
    m_sendHint->setObjectName(QStringLiteral("sendHintLabel"));
    m_sendHint->setForegroundRole(QPalette::PlaceholderText);
    m_sendHint->setWordWrap(true);

    m_intervalSpin = new QSpinBox(this);
    m_intervalSpin->setObjectName(QStringLiteral("intervalSpin"));
    m_intervalSpin->setRange(0, 3600000);
    m_intervalSpin->setValue(500);
    m_intervalSpin->setSingleStep(100);
    m_intervalSpin->setSuffix(tr(" ms"));
    m_intervalSpin->setSpecialValueText(tr("back to back"));
    m_intervalSpin->setToolTip(tr("From the start of one request to the start of the next; 0: as fast as the device answers"));
    m_countSpin = new QSpinBox(this);
    m_countSpin->setObjectName(QStringLiteral("countSpin"));
    m_countSpin->setRange(0, 100000000);
    m_countSpin->setValue(0);
    m_countSpin->setSpecialValueText(tr("until stopped"));
    m_countSpin->setSuffix(tr(" times"));
    m_pollButton = new QPushButton(tr("Start &poll"), this);
    m_pollButton->setObjectName(QStringLiteral("pollButton"));
    m_pollButton->setToolTip(tr("Send the request repeatedly (Ctrl+Shift+Return starts and stops)"));
    connect(m_pollButton, &QPushButton::clicked, this, &RequestComposer::togglePoll);

    auto *sendRow = new QHBoxLayout;
    sendRow->addWidget(m_sendButton);
    sendRow->addWidget(m_sendHint, 1);

    auto *poll = new QGroupBox(tr("Poll"), this);
    auto *pollRow = new QHBoxLayout(poll);
    auto *intervalLabel = new QLabel(tr("&Every"), poll);
    intervalLabel->setBuddy(m_intervalSpin);
    auto *countLabel = new QLabel(tr("&Count"), poll);
    countLabel->setBuddy(m_countSpin);
    pollRow->addWidget(intervalLabel);
    pollRow->addWidget(m_intervalSpin);
    pollRow->addWidget(countLabel);
    pollRow->addWidget(m_countSpin);
    pollRow->addStretch(1);
    pollRow->addWidget(m_pollButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs, 1);
    layout->addLayout(sendRow);
    layout->addWidget(poll);

    connect(m_raw, &RawRequestEditor::bytesChanged, this, &RequestComposer::onRawChanged);
    connect(m_form, &RequestForm::changed, this, &RequestComposer::onFormChanged);
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        if (m_tabs->currentWidget() == m_form)
            onFormChanged();
    });
    // After the handlers above, so the state is read once the Form has followed.
    connect(m_raw, &RawRequestEditor::bytesChanged, this, &RequestComposer::stateChanged);
    connect(m_intervalSpin, &QSpinBox::valueChanged, this, &RequestComposer::stateChanged);
    connect(m_countSpin, &QSpinBox::valueChanged, this, &RequestComposer::stateChanged);
    QAbstractItemModel *saved = m_raw->savedCombo()->model();
    connect(saved, &QAbstractItemModel::rowsInserted, this, &RequestComposer::stateChanged);
    connect(saved, &QAbstractItemModel::rowsRemoved, this, &RequestComposer::stateChanged);
    connect(saved, &QAbstractItemModel::modelReset, this, &RequestComposer::stateChanged);
}

RequestComposer::State RequestComposer::state() const
{
    State s;
    s.requestText = m_raw->text();
    s.request = bytes();
    s.intervalMs = m_intervalSpin->value();
    s.count = m_countSpin->value();
    s.savedRequests = m_raw->savedRequests();
    return s;
}

void RequestComposer::setState(const State &state)
{
    if (state.savedRequests != SavedRequests::load()) {
        SavedRequests::store(state.savedRequests);
        m_raw->reloadSavedRequests();
    }
    setRequestText(state.requestText);
    showRawTab();
    m_intervalSpin->setValue(state.intervalMs);
    m_countSpin->setValue(state.count);
}

QByteArray RequestComposer::bytes() const
{
    return m_raw->isValid() ? m_raw->bytes() : QByteArray();
}

void RequestComposer::setRequestText(const QString &hex)
{
    m_raw->setText(hex);
}

void RequestComposer::showRawTab()
{
    m_tabs->setCurrentWidget(m_raw);
}

void RequestComposer::showFormTab()
{
    m_tabs->setCurrentWidget(m_form);
}

void RequestComposer::setFraming(Framing framing)
{
    m_framing = framing;
    m_raw->setFraming(framing);
    m_form->setFraming(framing);
}

void RequestComposer::setUnitId(int unit)
{
    m_raw->setUnitId(unit);
    m_form->setUnitId(unit);
}

void RequestComposer::onRawChanged(const QByteArray &bytes, bool valid)
{
    updateActions();
    if (m_syncing || !valid)
        return;
    const AduParts parts = AduBuilder::parse(bytes, m_framing);
    if (!parts.complete || parts.pdu.isEmpty())
        return;
    m_syncing = true;
    if (m_form->setFromPdu(parts.pdu)) {
        m_form->setUnitId(parts.unitId);
        Q_EMIT unitIdSeen(parts.unitId);
    }
    m_syncing = false;
}

void RequestComposer::onFormChanged()
{
    // Only the tab in use writes: a change of link or unit does not rewrite bytes typed in Raw.
    if (m_syncing || m_tabs->currentWidget() != m_form)
        return;
    const QByteArray bytes = m_form->bytes();
    if (bytes.isEmpty())
        return;
    m_syncing = true;
    m_raw->setText(HexText::format(bytes));
    m_syncing = false;
    updateActions();
}

void RequestComposer::setLinkReady(bool ready)
{
    m_linkReady = ready;
    updateActions();
}

void RequestComposer::setPolling(bool polling)
{
    m_polling = polling;
    m_pollButton->setText(polling ? tr("Stop &poll") : tr("Start &poll"));
    m_pollAction->setText(polling ? tr("Stop &poll") : tr("Start &poll"));
    updateActions();
}

void RequestComposer::setListenOnly(bool listenOnly)
{
    m_listenOnly = listenOnly;
    updateActions();
}

void RequestComposer::updateActions()
{
    const bool haveBytes = !bytes().isEmpty();
    const bool canSend = m_linkReady && !m_listenOnly;
    m_sendAction->setEnabled(canSend && haveBytes && !m_polling);
    m_sendButton->setEnabled(m_sendAction->isEnabled());
    m_pollAction->setEnabled(canSend && (haveBytes || m_polling));
    m_pollButton->setEnabled(m_pollAction->isEnabled());
    const QString listening = tr("The link is listen-only: it monitors the bus and never sends. Disconnect and untick "
                                 "Listen only to send.");
    m_sendButton->setToolTip(m_listenOnly ? listening : tr("Send the request once (Ctrl+Return)"));
    m_pollButton->setToolTip(m_listenOnly ? listening : tr("Send the request repeatedly (Ctrl+Shift+Return starts and stops)"));
    if (m_listenOnly && m_linkReady)
        m_sendHint->setText(tr("Listen only: Send and Poll are off, nothing is sent to the bus."));
    else if (!m_linkReady)
        m_sendHint->setText(tr("Connect first (connection bar above)."));
    else if (!haveBytes)
        m_sendHint->setText(tr("Type a request (Raw) or build one (Form)."));
    else if (m_polling)
        m_sendHint->setText(tr("Polling\u2026"));
    else
        m_sendHint->setText(bytes().size() == 1 ? tr("1 byte ready.") : tr("%1 bytes ready.").arg(bytes().size()));
}

void RequestComposer::send()
{
    const QByteArray request = bytes();
    if (request.isEmpty() || !m_linkReady || m_listenOnly || m_polling)
        return;
    Q_EMIT sendRequested(request);
}

void RequestComposer::togglePoll()
{
    if (m_polling) {
        Q_EMIT stopPollRequested();
        return;
    }
    const QByteArray request = bytes();
    if (request.isEmpty() || !m_linkReady)
        return;
    Q_EMIT pollRequested(request, m_intervalSpin->value(), quint64(m_countSpin->value()));
}

} // namespace mbscope
