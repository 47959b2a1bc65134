#include "connectionbar.h"

#include "common/hexerrormark.h"
#include "serialportcombo.h"
#include "tapfields.h"
#include "tlsfilesfield.h"

#include <QtCore/QSettings>
#include <QtGui/QAction>
#include <QtSerialPort/QSerialPortInfo>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMenu>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

const QString kRecentKey = QStringLiteral("connection/recent");

struct KindChoice {
    LinkKind kind;
    const char *label;
};

constexpr KindChoice kKinds[] = {
    {LinkKind::Tcp, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "Modbus TCP")},
    {LinkKind::Tls, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "Modbus TCP Security (TLS)")},
    {LinkKind::RtuTcp, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "RTU over TCP")},
    {LinkKind::AsciiTcp, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "ASCII over TCP")},
    {LinkKind::Udp, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "Modbus UDP")},
    {LinkKind::RtuUdp, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "RTU over UDP")},
    {LinkKind::Rtu, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "RTU (serial)")},
    {LinkKind::Ascii, QT_TRANSLATE_NOOP("mbscope::ConnectionBar", "ASCII (serial)")},
};

QLabel *buddyLabel(const QString &text, QWidget *buddy, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setBuddy(buddy);
    return label;
}

} // namespace

ConnectionBar::ConnectionBar(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    rebuildRecentMenu();
    onKindChanged();
    watchFields();
}

// Every field, those of the TLS files and the serial port's editor included: a field added later
// cannot be missed. Connected after the bar's own handlers, so the state is read once they ran.
void ConnectionBar::watchFields()
{
    for (QLineEdit *edit : findChildren<QLineEdit *>())
        connect(edit, &QLineEdit::textChanged, this, &ConnectionBar::stateChanged);
    for (QSpinBox *spin : findChildren<QSpinBox *>())
        connect(spin, &QSpinBox::valueChanged, this, &ConnectionBar::stateChanged);
    for (QComboBox *combo : findChildren<QComboBox *>())
        connect(combo, &QComboBox::currentIndexChanged, this, &ConnectionBar::stateChanged);
    for (QCheckBox *check : findChildren<QCheckBox *>()) // Tap, Listen, the Tap row's Read-only
        connect(check, &QCheckBox::toggled, this, &ConnectionBar::stateChanged);
}

void ConnectionBar::buildUi()
{
    m_kindCombo = new QComboBox(this);
    m_kindCombo->setObjectName(QStringLiteral("linkKindCombo"));
    for (const KindChoice &choice : kKinds)
        m_kindCombo->addItem(tr(choice.label), int(choice.kind));
    // As wide as "ASCII over TCP", not as the longest choice: the bar fits 1024 px in both languages.
    m_kindCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_kindCombo->setMinimumContentsLength(15);

    // Network target
    m_hostEdit = new QLineEdit(QStringLiteral("127.0.0.1"), this);
    m_hostEdit->setObjectName(QStringLiteral("hostEdit"));
    m_hostEdit->setPlaceholderText(tr("host name or IP address"));
    m_hostEdit->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("192.168.127.254_")));
    // A host name is rarely longer than this; a wider field only pushes the port away from it.
    m_hostEdit->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("modbus-gateway.example.org____")));
    m_portSpin = new QSpinBox(this);
    m_portSpin->setObjectName(QStringLiteral("portSpin"));
    m_portSpin->setRange(1, 65535);
    m_portSpin->setValue(502);
    auto *network = new QWidget(this);
    m_networkPage = network;
    auto *networkRow = new QHBoxLayout(network);
    networkRow->setContentsMargins(0, 0, 0, 0);
    networkRow->addWidget(buddyLabel(tr("H&ost:"), m_hostEdit, network));
    networkRow->addWidget(m_hostEdit, 1);
    networkRow->addWidget(buddyLabel(tr("Port:"), m_portSpin, network));
    networkRow->addWidget(m_portSpin);

    // Serial target
    auto *ports = new SerialPortCombo(this);
    ports->setRefresh([this] { refreshSerialPorts(); });
    m_serialPortCombo = ports;
    m_serialPortCombo->setObjectName(QStringLiteral("serialPortCombo"));
    m_serialPortCombo->setEditable(true);
    m_serialPortCombo->setMinimumContentsLength(14);
    m_serialPortCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_serialPortCombo->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0"));
    auto *refresh = new QToolButton(this);
    refresh->setObjectName(QStringLiteral("refreshPortsButton"));
    refresh->setText(tr("Refresh"));
    refresh->setToolTip(tr("Look for serial ports again (after plugging in an adapter)"));
    connect(refresh, &QToolButton::clicked, this, &ConnectionBar::refreshSerialPorts);
    m_baudCombo = new QComboBox(this);
    m_baudCombo->setObjectName(QStringLiteral("baudCombo"));
    m_baudCombo->setEditable(true);
    for (int baud : {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200})
        m_baudCombo->addItem(QString::number(baud));
    m_baudCombo->setCurrentText(QStringLiteral("9600"));
    m_parityCombo = new QComboBox(this);
    m_parityCombo->setObjectName(QStringLiteral("parityCombo"));
    m_parityCombo->addItem(tr("Even"), QStringLiteral("E"));
    m_parityCombo->addItem(tr("Odd"), QStringLiteral("O"));
    m_parityCombo->addItem(tr("None"), QStringLiteral("N"));
    m_dataBitsCombo = new QComboBox(this);
    m_dataBitsCombo->setObjectName(QStringLiteral("dataBitsCombo"));
    for (int bits : {8, 7})
        m_dataBitsCombo->addItem(QString::number(bits), bits);
    m_stopBitsCombo = new QComboBox(this);
    m_stopBitsCombo->setObjectName(QStringLiteral("stopBitsCombo"));
    for (int bits : {1, 2})
        m_stopBitsCombo->addItem(QString::number(bits), bits);
    auto *serial = new QWidget(this);
    m_serialPage = serial;
    auto *serialRow = new QHBoxLayout(serial);
    serialRow->setContentsMargins(0, 0, 0, 0);
    serialRow->addWidget(buddyLabel(tr("P&ort:"), m_serialPortCombo, serial));
    serialRow->addWidget(m_serialPortCombo);
    serialRow->addWidget(refresh);
    serialRow->addWidget(buddyLabel(tr("&Baud:"), m_baudCombo, serial));
    serialRow->addWidget(m_baudCombo);
    serialRow->addWidget(buddyLabel(tr("Pa&rity:"), m_parityCombo, serial));
    serialRow->addWidget(m_parityCombo);
    serialRow->addWidget(buddyLabel(tr("&Data:"), m_dataBitsCombo, serial));
    serialRow->addWidget(m_dataBitsCombo);
    serialRow->addWidget(buddyLabel(tr("&Stop:"), m_stopBitsCombo, serial));
    serialRow->addWidget(m_stopBitsCombo);

    // One of the two pages is shown; a hidden page takes no room, so each keeps its natural width
    // (a stacked widget would give the short network page the serial page's width).
    serial->hide();

    m_unitSpin = new QSpinBox(this);
    m_unitSpin->setObjectName(QStringLiteral("unitSpin"));
    m_unitSpin->setRange(0, 255);
    m_unitSpin->setValue(1);
    m_unitSpin->setToolTip(tr("Unit (slave) id put into built and completed requests; 0 is a broadcast on serial lines"));
    m_timeoutSpin = new QSpinBox(this);
    m_timeoutSpin->setObjectName(QStringLiteral("timeoutSpin"));
    m_timeoutSpin->setRange(10, 60000);
    m_timeoutSpin->setSingleStep(100);
    m_timeoutSpin->setValue(1000);
    m_timeoutSpin->setSuffix(tr(" ms"));
    m_timeoutSpin->setToolTip(tr("How long to wait for an answer before the request counts as timed out"));

    // In the Recent menu, not a button of its own: the bar must fit a 1024-pixel screen.
    m_paceAction = new QAction(tr("Device &pace…"), this);
    m_paceAction->setObjectName(QStringLiteral("paceAction"));
    m_paceAction->setToolTip(tr("The device's pace: a gap between requests, a wait after connecting, a new connection for "
                                "each request (by hand or from a device profile)"));
    connect(m_paceAction, &QAction::triggered, this, &ConnectionBar::editPace);

    m_listenOnlyCheck = new QCheckBox(tr("L&isten"), this);
    m_listenOnlyCheck->setObjectName(QStringLiteral("listenOnlyCheck"));
    m_listenOnlyCheck->setToolTip(tr("Monitor a bus another master drives: every exchange on the line is shown, paired "
                                     "and measured, and nothing is ever sent (serial links, RTU or ASCII over TCP)"));

    m_tapCheck = new QCheckBox(tr("Tap"), this);
    m_tapCheck->setObjectName(QStringLiteral("tapCheck"));
    m_tapCheck->setToolTip(tr("Put the window between masters and this device: masters connect to the Tap row's URLs, "
                              "each request goes on to the target above (or a route's), the answer back; both legs "
                              "are shown, decoded and recorded (mbscope tap in the window)"));
    m_tapFields = new TapFields(this);
    m_tapFields->setObjectName(QStringLiteral("tapFields"));
    m_tapFields->hide();
    connect(m_tapFields, &TapFields::edited, this, &ConnectionBar::clearError);
    // Listen and Tap are two ways of not sending from the window: one at a time.
    connect(m_listenOnlyCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            m_tapCheck->setChecked(false);
    });
    connect(m_tapCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            m_listenOnlyCheck->setChecked(false);
        m_tapFields->setVisible(on);
        clearError();
    });

    m_connectButton = new QPushButton(tr("&Connect"), this);
    m_connectButton->setObjectName(QStringLiteral("connectButton"));
    m_connectButton->setDefault(false);
    m_connectButton->setMinimumWidth(fontMetrics().horizontalAdvance(tr("Disconnect")) + 32);
    m_recentButton = new QToolButton(this);
    m_recentButton->setObjectName(QStringLiteral("recentButton"));
    m_recentButton->setText(tr("Recent"));
    m_recentButton->setPopupMode(QToolButton::InstantPopup);
    m_recentButton->setMenu(new QMenu(m_recentButton));
    m_recentButton->setToolTip(tr("Targets connected to before, and the device's pace"));

    // TLS's files on a row of their own, shown for tls:// only.
    m_tlsFiles = new TlsFilesField(this);
    m_tlsFiles->setObjectName(QStringLiteral("tlsFiles"));
    m_tlsFiles->hide();
    connect(m_tlsFiles, &TlsFilesField::edited, this, &ConnectionBar::clearError);

    m_errorLabel = hexerrormark::newErrorLabel(QStringLiteral("connectionErrorLabel"), this);
    m_keptLabel = new QLabel(this);
    m_keptLabel->setObjectName(QStringLiteral("keptOptionsLabel"));
    m_keptLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_keptLabel->hide();

    auto *row = new QHBoxLayout;
    row->addWidget(buddyLabel(tr("&Link:"), m_kindCombo, this));
    row->addWidget(m_kindCombo);
    row->addWidget(m_networkPage);
    row->addWidget(m_serialPage);
    row->addWidget(buddyLabel(tr("&Unit:"), m_unitSpin, this));
    row->addWidget(m_unitSpin);
    row->addWidget(buddyLabel(tr("Ti&meout:"), m_timeoutSpin, this));
    row->addWidget(m_timeoutSpin);
    row->addWidget(m_keptLabel);
    row->addWidget(m_listenOnlyCheck);
    row->addWidget(m_tapCheck);
    row->addWidget(m_connectButton);
    row->addWidget(m_recentButton);
    row->addStretch(1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->setSpacing(2);
    layout->addLayout(row);
    layout->addWidget(m_tlsFiles);
    layout->addWidget(m_tapFields);
    layout->addWidget(m_errorLabel);

    connect(m_kindCombo, &QComboBox::currentIndexChanged, this, &ConnectionBar::onKindChanged);
    connect(m_connectButton, &QPushButton::clicked, this, &ConnectionBar::onConnectClicked);
    connect(m_unitSpin, &QSpinBox::valueChanged, this, &ConnectionBar::unitIdChanged);
    for (QLineEdit *edit : {m_hostEdit})
        connect(edit, &QLineEdit::textEdited, this, &ConnectionBar::clearError);
}

namespace {

// The links a bus monitor can listen on (BusMonitor::unsupportedReason).
bool canListen(LinkKind kind)
{
    return kind == LinkKind::Rtu || kind == LinkKind::Ascii || kind == LinkKind::RtuTcp || kind == LinkKind::AsciiTcp;
}

} // namespace

LinkKind ConnectionBar::kind() const
{
    return LinkKind(m_kindCombo->currentData().toInt());
}

Framing ConnectionBar::framing() const
{
    LinkUrl probe;
    probe.kind = kind();
    return probe.framing();
}

namespace {

// The URL's options no field of the bar shows (its own defaults for everything else).
QStringList hiddenOptions(const LinkUrl &url)
{
    LinkUrl shown = url;
    const LinkUrl defaults;
    shown.serial.turnaroundUs = defaults.serial.turnaroundUs;
    shown.serial.rs485 = defaults.serial.rs485;
    shown.delimited = defaults.delimited;
    shown.connectTimeoutMs = defaults.connectTimeoutMs;
    shown.listen = defaults.listen;
    shown.busy = defaults.busy;
    shown.gap = defaults.gap;
    shown.warmUp = defaults.warmUp;
    shown.closeAfterAnswer = defaults.closeAfterAnswer;
    const auto options = [](const QString &text) {
        const qsizetype q = text.indexOf(QLatin1Char('?'));
        return q < 0 ? QStringList() : text.mid(q + 1).split(QLatin1Char('&'), Qt::SkipEmptyParts);
    };
    const QStringList plain = options(shown.toString());
    QStringList hidden;
    for (const QString &option : options(url.toString())) {
        if (!plain.contains(option))
            hidden.append(option);
    }
    return hidden;
}

} // namespace

QString ConnectionBar::keptOptions() const
{
    if (!m_kept || m_kept->kind != kind())
        return {};
    return hiddenOptions(*m_kept).join(QLatin1Char('&'));
}

PaceDialog::Pace ConnectionBar::pace() const
{
    if (!m_kept || m_kept->kind != kind())
        return {};
    return PaceDialog::Pace{m_kept->gap, m_kept->warmUp, m_kept->closeAfterAnswer};
}

void ConnectionBar::setPace(const PaceDialog::Pace &pace)
{
    if (!m_kept || m_kept->kind != kind()) {
        m_kept = LinkUrl{};
        m_kept->kind = kind();
    }
    m_kept->gap = pace.gap;
    m_kept->warmUp = pace.warmUp;
    m_kept->closeAfterAnswer = pace.closeAfterAnswer && !m_kept->isSerial() && !m_kept->isDatagram();
    showKept();
    Q_EMIT stateChanged();
}

void ConnectionBar::editPace()
{
    LinkUrl probe;
    probe.kind = kind();
    PaceDialog dialog(pace(), !probe.isSerial() && !probe.isDatagram(), this);
    if (dialog.exec() == QDialog::Accepted)
        setPace(dialog.pace());
}

void ConnectionBar::showKept()
{
    const QString kept = keptOptions();
    m_keptLabel->setText(kept.isEmpty() ? QString() : QStringLiteral("+ ") + kept);
    m_keptLabel->setToolTip(tr("Options of this target that no field here shows, used on Connect: %1. They came with the "
                               "target (a recent target, a session or the command line) or from Device pace…; choose another link type "
                               "to drop them.")
                                .arg(kept));
    m_keptLabel->setVisible(!kept.isEmpty());
}

void ConnectionBar::onKindChanged()
{
    showKept();
    const bool serial = kind() == LinkKind::Rtu || kind() == LinkKind::Ascii;
    m_networkPage->setVisible(!serial);
    m_serialPage->setVisible(serial);
    m_tlsFiles->setVisible(kind() == LinkKind::Tls);
    m_listenOnlyCheck->setEnabled(canListen(kind()) && !m_connected);
    // The port follows the link type while it is the other type's default: 802 is MODBUS/TCP
    // Security's port (5.1), 502 Modbus TCP's.
    if (kind() == LinkKind::Tls && m_portSpin->value() == 502)
        m_portSpin->setValue(802);
    else if (m_lastKind == LinkKind::Tls && kind() != LinkKind::Tls && m_portSpin->value() == 802)
        m_portSpin->setValue(502);
    m_lastKind = kind();
    if (serial && m_serialPortCombo->count() == 0)
        refreshSerialPorts();
    // ASCII carries 7 data bits by default (Serial Line V1.02, 2.5.2), RTU always 8.
    m_dataBitsCombo->setCurrentIndex(m_dataBitsCombo->findData(kind() == LinkKind::Ascii ? 7 : 8));
    clearError();
    Q_EMIT framingChanged(framing());
}

void ConnectionBar::refreshSerialPorts()
{
    const QString current = m_serialPortCombo->currentText();
    m_serialPortCombo->clear();
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &port : ports) {
        QString detail = port.description();
        if (!port.manufacturer().isEmpty() && !detail.contains(port.manufacturer()))
            detail += QStringLiteral(" (%1)").arg(port.manufacturer());
        m_serialPortCombo->addItem(port.systemLocation(), port.systemLocation());
        m_serialPortCombo->setItemData(m_serialPortCombo->count() - 1, detail, Qt::ToolTipRole);
    }
    m_serialPortCombo->setToolTip(ports.isEmpty() ? tr("No serial port found: plug in the adapter and press Refresh, "
                                                       "or type the device path")
                                                  : tr("Serial ports found: %1").arg(ports.size()));
    m_serialPortCombo->setCurrentText(current);
}

std::optional<LinkUrl> ConnectionBar::url()
{
    // What no field shows comes from the URL set last, while the link type is the same; the
    // fields then give the rest.
    LinkUrl url = m_kept && m_kept->kind == kind() ? *m_kept : LinkUrl{};
    url.kind = kind();
    if (url.isSerial()) {
        url.serial.device = m_serialPortCombo->currentText().trimmed();
        if (url.serial.device.isEmpty()) {
            showError(QSerialPortInfo::availablePorts().isEmpty()
                          ? tr("Choose a serial port: none was found. Plug in the adapter and press Refresh, or type its path (/dev/ttyUSB0).")
                          : tr("Choose a serial port from the list (or type its path, e.g. /dev/ttyUSB0)."));
            m_serialPortCombo->setFocus();
            return std::nullopt;
        }
        bool ok = false;
        url.serial.baud = m_baudCombo->currentText().trimmed().toInt(&ok);
        if (!ok || url.serial.baud <= 0) {
            showError(tr("Baud rate '%1' is not a number: choose one from the list (9600, 19200...).")
                          .arg(m_baudCombo->currentText()));
            m_baudCombo->setFocus();
            return std::nullopt;
        }
        url.serial.parity = m_parityCombo->currentData().toString().at(0).toLatin1();
        url.serial.dataBits = m_dataBitsCombo->currentData().toInt();
        url.serial.stopBits = m_stopBitsCombo->currentData().toInt();
        if (url.kind == LinkKind::Rtu && url.serial.dataBits != 8) {
            showError(tr("RTU needs 8 data bits (Serial Line V1.02, 2.5.1): set Data to 8."));
            m_dataBitsCombo->setFocus();
            return std::nullopt;
        }
    } else {
        url.host = m_hostEdit->text().trimmed();
        if (url.host.isEmpty()) {
            showError(tr("Type the device's host name or IP address (for example 192.168.127.254)."));
            m_hostEdit->setFocus();
            return std::nullopt;
        }
        if (url.host.contains(QLatin1Char(' ')) || url.host.contains(QLatin1Char('/'))) {
            showError(tr("Host '%1' is not a host name or IP address: type only the address, the port goes in Port.")
                          .arg(url.host));
            m_hostEdit->setFocus();
            return std::nullopt;
        }
        url.port = quint16(m_portSpin->value());
        if (url.kind == LinkKind::Tls) {
            const QString problem = m_tlsFiles->check();
            if (!problem.isEmpty()) {
                showError(problem);
                return std::nullopt;
            }
            url.tls = m_tlsFiles->settings();
        }
    }
    url.responseTimeoutMs = m_timeoutSpin->value();
    // Round trip through the parser: the URL the bar produces is one the CLI accepts too.
    const LinkUrl::Result checked = LinkUrl::parse(url.toString());
    if (!checked.url) {
        showError(tr("This target cannot be used: %1").arg(checked.error));
        return std::nullopt;
    }
    clearError();
    return checked.url;
}

void ConnectionBar::setUrl(const LinkUrl &url)
{
    m_kept = url;
    m_kindCombo->setCurrentIndex(qMax(0, m_kindCombo->findData(int(url.kind))));
    showKept();
    if (url.isSerial()) {
        m_serialPortCombo->setCurrentText(url.serial.device);
        m_baudCombo->setCurrentText(QString::number(url.serial.baud));
        m_parityCombo->setCurrentIndex(qMax(0, m_parityCombo->findData(QString(QLatin1Char(url.serial.parity)))));
        m_dataBitsCombo->setCurrentIndex(qMax(0, m_dataBitsCombo->findData(url.serial.dataBits)));
        m_stopBitsCombo->setCurrentIndex(qMax(0, m_stopBitsCombo->findData(url.serial.stopBits)));
    } else {
        m_hostEdit->setText(url.host);
        m_portSpin->setValue(url.port);
        m_tlsFiles->setSettings(url.tls);
    }
    if (url.responseTimeoutMs > 0)
        m_timeoutSpin->setValue(url.responseTimeoutMs);
    clearError();
}

ConnectionBar::State ConnectionBar::state()
{
    return State{url(), timeoutMs()};
}

void ConnectionBar::setState(const State &state)
{
    if (!state.target)
        return;
    LinkUrl target = *state.target;
    if (target.responseTimeoutMs < 0 && state.timeoutMs > 0)
        target.responseTimeoutMs = state.timeoutMs;
    setUrl(target);
}

int ConnectionBar::unitId() const
{
    return m_unitSpin->value();
}

void ConnectionBar::setUnitId(int unit)
{
    m_unitSpin->setValue(unit);
}

int ConnectionBar::timeoutMs() const
{
    return m_timeoutSpin->value();
}

void ConnectionBar::setConnected(bool connected)
{
    m_connected = connected;
    m_connectButton->setText(connected ? tr("Dis&connect") : tr("&Connect"));
    // The target of a live link is what the link uses: change it by disconnecting first.
    for (QWidget *w : std::initializer_list<QWidget *>{m_kindCombo, m_networkPage, m_serialPage, m_tlsFiles, m_timeoutSpin, m_recentButton})
        w->setEnabled(!connected);
    m_listenOnlyCheck->setEnabled(!connected && canListen(kind()));
    m_tapCheck->setEnabled(!connected);
    m_tapFields->setRunning(connected && isTap());
}

bool ConnectionBar::isListenOnly() const
{
    return m_listenOnlyCheck->isChecked() && canListen(kind());
}

void ConnectionBar::setListenOnly(bool listenOnly)
{
    m_listenOnlyCheck->setChecked(listenOnly);
}

bool ConnectionBar::isTap() const
{
    return m_tapCheck->isChecked();
}

void ConnectionBar::setTap(bool tap)
{
    m_tapCheck->setChecked(tap);
}

std::optional<TapSetup> ConnectionBar::tapSetup()
{
    const std::optional<LinkUrl> target = url();
    if (!target)
        return std::nullopt;
    QString error;
    std::optional<TapSetup> setup = m_tapFields->setup(*target, timeoutMs(), &error);
    if (!setup)
        showError(error);
    return setup;
}

void ConnectionBar::showError(const QString &message)
{
    m_errorLabel->setText(message);
    m_errorLabel->setVisible(!message.isEmpty());
}

void ConnectionBar::showLinkFailure(const QString &linkMessage)
{
    showError(tr("The link failed: %1. Check that the device is powered and reachable at this address, then send "
                 "again (the link reopens), or press Disconnect to change the target.")
                  .arg(linkMessage));
}

void ConnectionBar::clearError()
{
    showError({});
}

QString ConnectionBar::errorText() const
{
    return m_errorLabel->isVisibleTo(this) ? m_errorLabel->text() : QString();
}

void ConnectionBar::onConnectClicked()
{
    if (m_connected) {
        Q_EMIT disconnectRequested();
        return;
    }
    if (isTap()) {
        if (const std::optional<TapSetup> setup = tapSetup()) {
            m_tapFields->remember();
            Q_EMIT tapRequested(*setup);
        }
        return;
    }
    if (const std::optional<LinkUrl> target = url()) {
        if (isListenOnly())
            Q_EMIT listenRequested(*target);
        else
            Q_EMIT connectRequested(*target);
    }
}

void ConnectionBar::addRecent(const LinkUrl &url)
{
    QSettings settings;
    QStringList recent = settings.value(kRecentKey).toStringList();
    const QString text = url.toString();
    recent.removeAll(text);
    recent.prepend(text);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(kRecentKey, recent);
    rebuildRecentMenu();
}

QStringList ConnectionBar::recentTargets() const
{
    return QSettings().value(kRecentKey).toStringList();
}

void ConnectionBar::rebuildRecentMenu()
{
    QMenu *menu = m_recentButton->menu();
    menu->clear();
    const QStringList recent = recentTargets();
    for (const QString &text : recent) {
        // A URL's options are joined by '&', which a menu takes for a shortcut mark.
        menu->addAction(QString(text).replace(QLatin1Char('&'), QStringLiteral("&&")), this, [this, text] {
            const LinkUrl::Result parsed = LinkUrl::parse(text);
            if (parsed.url)
                setUrl(*parsed.url);
            else
                showError(tr("The recent target '%1' cannot be read: %2").arg(text, parsed.error));
        });
    }
    if (recent.isEmpty())
        menu->addAction(tr("(no recent targets yet)"))->setEnabled(false);
    menu->addSeparator();
    menu->addAction(m_paceAction);
}

} // namespace mbscope
