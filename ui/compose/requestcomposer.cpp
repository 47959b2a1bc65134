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
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPlainTextEdit>
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
    m_tabs->addTab(m_raw, tr("Ra&w"));
    m_tabs->addTab(m_form, tr("Form"));

    // Ctrl+Return sends and Ctrl+Shift+Return starts or stops the poll from anywhere in the window
    // (the traffic list, the register table): a running poll is always one key from stopping.
    m_sendAction = new QAction(tr("&Send"), this);
    m_sendAction->setObjectName(QStringLiteral("sendAction"));
    m_sendAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    m_sendAction->setShortcutContext(Qt::WindowShortcut);
    m_sendAction->setToolTip(tr("Send the request once (Ctrl+Return)"));
    addAction(m_sendAction);
    connect(m_sendAction, &QAction::triggered, this, &RequestComposer::send);
    m_pollAction = new QAction(tr("Start &poll"), this);
    m_pollAction->setObjectName(QStringLiteral("pollAction"));
    m_pollAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Return));
    m_pollAction->setShortcutContext(Qt::WindowShortcut);
    addAction(m_pollAction);
    connect(m_pollAction, &QAction::triggered, this, &RequestComposer::togglePoll);

    m_sendButton = new QPushButton(tr("Se&nd  (Ctrl+Return)"), this);
    m_sendButton->setObjectName(QStringLiteral("sendButton"));
    m_sendButton->setToolTip(tr("Send the request once (Ctrl+Return)"));
    QFont bold = m_sendButton->font();
    bold.setBold(true);
    m_sendButton->setFont(bold);
    m_sendButton->setMinimumWidth(m_sendButton->fontMetrics().horizontalAdvance(QStringLiteral("Send  (Ctrl+Return)")));
    m_sendButton->setText(tr("Se&nd  (Ctrl+Return)"));
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
    auto *intervalLabel = new QLabel(tr("Ever&y"), poll);
    intervalLabel->setBuddy(m_intervalSpin);
    auto *countLabel = new QLabel(tr("Count"), poll);
    countLabel->setBuddy(m_countSpin);
    pollRow->addWidget(intervalLabel);
    pollRow->addWidget(m_intervalSpin);
    pollRow->addWidget(countLabel);
    pollRow->addWidget(m_countSpin);
    pollRow->addStretch(1);
    pollRow->addWidget(m_pollButton);

    // Offered when the link type changed under a typed frame: never send the old framing silently.
    m_conversionBar = new QWidget(this);
    m_conversionBar->setObjectName(QStringLiteral("conversionBar"));
    m_conversionText = new QLabel(m_conversionBar);
    m_conversionText->setWordWrap(true);
    m_conversionText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *convert = new QPushButton(tr("Convert"), m_conversionBar);
    convert->setObjectName(QStringLiteral("convertButton"));
    connect(convert, &QPushButton::clicked, this, &RequestComposer::acceptConversion);
    auto *keep = new QPushButton(tr("Keep as typed"), m_conversionBar);
    keep->setObjectName(QStringLiteral("keepButton"));
    connect(keep, &QPushButton::clicked, this, &RequestComposer::keepAsTyped);
    auto *conversionLayout = new QVBoxLayout(m_conversionBar);
    conversionLayout->setContentsMargins(0, 0, 0, 0);
    conversionLayout->addWidget(m_conversionText);
    auto *conversionButtons = new QHBoxLayout;
    conversionButtons->addWidget(convert);
    conversionButtons->addWidget(keep);
    conversionButtons->addStretch(1);
    conversionLayout->addLayout(conversionButtons);
    m_conversionBar->hide();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs, 1);
    layout->addWidget(m_conversionBar);
    layout->addLayout(sendRow);
    layout->addWidget(poll);

    connect(m_raw, &RawRequestEditor::bytesChanged, this, &RequestComposer::onRawChanged);
    connect(m_form, &RequestForm::changed, this, &RequestComposer::onFormChanged);
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        if (m_tabs->currentWidget() == m_form)
            onFormChanged();
        else
            updateActions();
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
    // On the Form tab, a form that refuses its fields sends nothing: not the last bytes it made,
    // which the Raw tab still holds (try-out 8, item 3: the request must not change silently).
    if (m_tabs && m_tabs->currentWidget() == m_form && m_form->bytes().isEmpty())
        return {};
    return m_raw->isValid() ? m_raw->bytes() : QByteArray();
}

void RequestComposer::setRequestText(const QString &hex)
{
    m_raw->setText(hex);
}

QMenu *RequestComposer::addMenu(QMenuBar *menuBar)
{
    QMenu *request = menuBar->addMenu(tr("&Request"));
    request->addAction(m_sendAction);
    request->addAction(m_pollAction);
    request->addSeparator();
    QAction *focusRaw = request->addAction(tr("&Edit raw bytes"), this, [this] {
        showRawTab();
        m_raw->editor()->setFocus();
    });
    focusRaw->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    QAction *form = request->addAction(tr("Build with the &form"), this, &RequestComposer::showFormTab);
    form->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    return request;
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
    const Framing before = m_framing;
    m_framing = framing;
    m_raw->setFraming(framing);
    m_form->setFraming(framing);
    if (before != framing)
        offerConversion(before);
}

namespace {

bool isMbap(Framing framing)
{
    return framing == Framing::Tcp || framing == Framing::Udp;
}

} // namespace

void RequestComposer::offerConversion(Framing from)
{
    dismissConversion();
    const QByteArray typed = bytes();
    if (typed.isEmpty() || m_syncing)
        return;
    // Only a whole, correct frame of the old framing is converted: anything else may be meant.
    const AduParts parts = AduBuilder::parse(typed, from);
    if (!parts.complete || parts.pdu.isEmpty() || !parts.error.isEmpty())
        return;
    if (!isMbap(from) && !parts.checksumValid())
        return;
    if (isMbap(from) == isMbap(m_framing) && from != Framing::Ascii && m_framing != Framing::Ascii)
        return; // RTU and RTU over TCP, or MBAP on TCP and UDP: the same bytes
    AduOptions options;
    options.framing = m_framing;
    options.unitId = parts.unitId;
    options.transactionId = isMbap(from) ? parts.transactionId : 1;
    const QByteArray converted = AduBuilder::complete(parts.pdu, options);
    if (converted.isEmpty() || converted == typed)
        return;
    m_converted = converted;
    QString change;
    if (isMbap(m_framing))
        change = tr("remove the check sum, add an MBAP header");
    else if (isMbap(from))
        change = tr("remove the MBAP header, add the check sum");
    else
        change = tr("the same unit and PDU in the new framing");
    m_conversionText->setText(tr("<b>The Raw bytes are a %1 frame; the link now takes %2 frames.</b> Sent as they are, "
                                 "the device would misread them. Convert (%3) sends:<br><code>%4</code>")
                                  .arg(framingName(from).toUpper(), framingName(m_framing).toUpper(), change,
                                       HexText::format(converted)));
    m_conversionBar->show();
    updateActions();
}

void RequestComposer::dismissConversion()
{
    if (m_converted.isEmpty() && m_conversionBar->isHidden())
        return;
    m_converted.clear();
    m_conversionBar->hide();
    updateActions();
}

void RequestComposer::acceptConversion()
{
    const QByteArray converted = m_converted;
    dismissConversion();
    if (!converted.isEmpty())
        m_raw->setText(HexText::format(converted));
}

void RequestComposer::keepAsTyped()
{
    dismissConversion();
}

void RequestComposer::setUnitId(int unit)
{
    m_raw->setUnitId(unit);
    m_form->setUnitId(unit);
}

void RequestComposer::onRawChanged(const QByteArray &bytes, bool valid)
{
    // The user edited the bytes: what they typed now is what they mean.
    if (!m_converted.isEmpty() && bytes != m_converted)
        dismissConversion();
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
    if (bytes.isEmpty()) {
        updateActions(); // Send waits until the form is right
        return;
    }
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

void RequestComposer::setTapping(bool tapping)
{
    m_tapping = tapping;
    updateActions();
}

void RequestComposer::updateActions()
{
    const bool haveBytes = !bytes().isEmpty() && m_converted.isEmpty();
    const bool canSend = m_linkReady && !m_listenOnly && !m_tapping;
    m_sendAction->setEnabled(canSend && haveBytes && !m_polling);
    m_sendButton->setEnabled(m_sendAction->isEnabled());
    m_pollAction->setEnabled(canSend && (haveBytes || m_polling));
    m_pollButton->setEnabled(m_pollAction->isEnabled());
    const QString listening = tr("The link is listen-only: it monitors the bus and never sends. Disconnect and untick "
                                 "Listen to send.");
    const QString tapping = tr("The window is a tap: the masters send through it. Press Disconnect to stop the tap and "
                               "send from here.");
    m_sendButton->setToolTip(m_tapping ? tapping : m_listenOnly ? listening : tr("Send the request once (Ctrl+Return)"));
    m_pollButton->setToolTip(m_tapping     ? tapping
                             : m_listenOnly ? listening
                                            : tr("Send the request repeatedly (Ctrl+Shift+Return starts and stops)"));
    if (m_tapping && m_linkReady)
        m_sendHint->setText(tr("Tap: Send and Poll are off; the masters' requests go through the tap."));
    else if (m_listenOnly && m_linkReady)
        m_sendHint->setText(tr("Listen only: Send and Poll are off, nothing is sent to the bus."));
    else if (!m_linkReady)
        m_sendHint->setText(tr("Connect first (connection bar above)."));
    else if (!m_converted.isEmpty())
        m_sendHint->setText(tr("Convert the bytes for the new link, or keep them as typed."));
    else if (!haveBytes && m_tabs->currentWidget() == m_form && !m_form->errorText().isEmpty())
        m_sendHint->setText(tr("The form refuses this request: the reason is under the fields."));
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
    if (request.isEmpty() || !m_linkReady || m_listenOnly || m_tapping || m_polling || !m_converted.isEmpty())
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
    if (request.isEmpty() || !m_linkReady || !m_converted.isEmpty())
        return;
    Q_EMIT pollRequested(request, m_intervalSpin->value(), quint64(m_countSpin->value()));
}

} // namespace mbscope
