#include "tapfields.h"

#include "profile/profileloader.h"
#include "time/duration.h"

#include <QtCore/QLocale>
#include <QtCore/QRegularExpression>
#include <QtCore/QSettings>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

const QString kListenKey = QStringLiteral("tap/listen");
const QString kRoutesKey = QStringLiteral("tap/routes");
const QString kReadOnlyKey = QStringLiteral("tap/readOnly");
const QString kRefusalKey = QStringLiteral("tap/refusal");
const QString kNoAnswerKey = QStringLiteral("tap/noAnswer");
const QString kRetriesKey = QStringLiteral("tap/retries");
const QString kFaultsKey = QStringLiteral("tap/faults");

QStringList words(const QString &text)
{
    static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
    return text.split(separators, Qt::SkipEmptyParts);
}

QLabel *buddyLabel(const QString &text, QWidget *buddy, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setBuddy(buddy);
    return label;
}

} // namespace

TapFields::TapFields(QWidget *parent)
    : QWidget(parent)
{
    const QSettings settings;
    m_listenEdit = new QLineEdit(settings.value(kListenKey, QStringLiteral("tcp://127.0.0.1:5020")).toString(), this);
    m_listenEdit->setObjectName(QStringLiteral("tapListenEdit"));
    m_listenEdit->setPlaceholderText(tr("tcp://0.0.0.0:502"));
    m_listenEdit->setToolTip(tr("Where the masters (a SCADA, a PLC, mbpoll...) connect, as if to the device: one URL or "
                                "several separated by spaces, tcp://, rtu-tcp://, udp://, tls:// or a serial port "
                                "rtu:///dev/ttyUSB0?baud=19200&parity=N (port 0: any free port)"));
    m_listenEdit->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("rtu-tcp://127.0.0.1:5020__")));
    m_routesEdit = new QLineEdit(settings.value(kRoutesKey).toString(), this);
    m_routesEdit->setObjectName(QStringLiteral("tapRoutesEdit"));
    m_routesEdit->setPlaceholderText(tr("none: every unit to the target"));
    m_routesEdit->setToolTip(tr("Units to other devices, separated by spaces, each UNITS[:DEVICE_UNIT]=URL: 1-10=rtu:///dev/ttyUSB0 "
                                "or 1:17=tcp://10.0.0.5:502 (the master's unit 1 is the device's unit 17). The first route "
                                "that serves a unit takes it; the target above takes the units no route serves. A route's URL may give its "
                                "own timeout= and retries= (1:17=tcp://10.0.0.5:502?timeout=300ms&retries=0)."));
    m_readOnlyCheck = new QCheckBox(tr("Read-only"), this);
    m_readOnlyCheck->setObjectName(QStringLiteral("tapReadOnlyCheck"));
    m_readOnlyCheck->setChecked(settings.value(kReadOnlyKey, false).toBool());
    m_readOnlyCheck->setToolTip(tr("Forward no write (05, 06, 0F, 10, 15, 16, 17) and no Diagnostics sub-function that "
                                   "changes a device: refused and counted, so a tap on a production line cannot change "
                                   "a device by accident"));
    m_refusalCombo = new QComboBox(this);
    m_refusalCombo->setObjectName(QStringLiteral("tapRefusalCombo"));
    m_refusalCombo->addItem(tr("exception 01"), int(TapSettings::Refusal::Exception));
    m_refusalCombo->addItem(tr("silence"), int(TapSettings::Refusal::Silence));
    m_refusalCombo->setCurrentIndex(qMax(0, m_refusalCombo->findData(settings.value(kRefusalKey, 0).toInt())));
    m_refusalCombo->setToolTip(tr("What a refused write gets: exception 01 (illegal function) or no answer"));
    m_noAnswerCombo = new QComboBox(this);
    m_noAnswerCombo->setObjectName(QStringLiteral("tapNoAnswerCombo"));
    m_noAnswerCombo->addItem(tr("auto"), int(TapSettings::NoAnswer::Auto));
    m_noAnswerCombo->addItem(tr("exception 0B/0A"), int(TapSettings::NoAnswer::Exception));
    m_noAnswerCombo->addItem(tr("silence"), int(TapSettings::NoAnswer::Silence));
    m_noAnswerCombo->setCurrentIndex(qMax(0, m_noAnswerCombo->findData(settings.value(kNoAnswerKey, 0).toInt())));
    m_noAnswerCombo->setToolTip(tr("What a master gets when its device does not answer (exception 0B) or no route serves "
                                   "its unit (exception 0A): auto gives exceptions to Modbus/TCP and UDP masters and "
                                   "silence to serial ones"));
    m_retriesSpin = new QSpinBox(this);
    m_retriesSpin->setObjectName(QStringLiteral("tapRetriesSpin"));
    m_retriesSpin->setRange(0, 100);
    m_retriesSpin->setValue(settings.value(kRetriesKey, 0).toInt());
    m_retriesSpin->setToolTip(tr("Further attempts of a read after a timeout or a damaged answer, before the master gets its 0B "
                                 "or silence (a write is sent once), unless a route's URL gives retries="));
    m_faultsEdit = new QLineEdit(settings.value(kFaultsKey).toString(), this);
    m_faultsEdit->setObjectName(QStringLiteral("tapFaultsEdit"));
    m_faultsEdit->setPlaceholderText(tr("none"));
    m_faultsEdit->setToolTip(tr("A fault rules file (the simulator's rules: drop, delay, exception, wrong checksum, wrong unit, "
                                "close...; docs/profiles.md \"Faults\") applied to the devices' answers on their way back, so a "
                                "master's handling of a misbehaving device can be tried without touching either. Read when the "
                                "tap starts; empty: every answer passes unchanged"));
    m_countersLabel = new QLabel(this);
    m_countersLabel->setObjectName(QStringLiteral("tapCountersLabel"));
    m_countersLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_countersLabel->hide();

    auto *row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(buddyLabel(tr("Masters connect to:"), m_listenEdit, this));
    row->addWidget(m_listenEdit, 2);
    row->addWidget(buddyLabel(tr("Routes:"), m_routesEdit, this));
    row->addWidget(m_routesEdit, 3);
    row->addWidget(m_readOnlyCheck);
    row->addWidget(m_refusalCombo);
    row->addWidget(buddyLabel(tr("No answer:"), m_noAnswerCombo, this));
    row->addWidget(m_noAnswerCombo);
    row->addWidget(buddyLabel(tr("Retries:"), m_retriesSpin, this));
    row->addWidget(m_retriesSpin);
    row->addWidget(buddyLabel(tr("Faults:"), m_faultsEdit, this));
    row->addWidget(m_faultsEdit, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(row);
    layout->addWidget(m_countersLabel);

    m_refusalCombo->setEnabled(m_readOnlyCheck->isChecked());
    connect(m_readOnlyCheck, &QCheckBox::toggled, m_refusalCombo, &QWidget::setEnabled);
    for (QLineEdit *edit : {m_listenEdit, m_routesEdit, m_faultsEdit})
        connect(edit, &QLineEdit::textEdited, this, &TapFields::edited);
}

std::optional<TapSetup> TapFields::setup(const LinkUrl &target, int timeoutMs, QString *error) const
{
    TapSetup setup;
    const QStringList listen = words(m_listenEdit->text());
    if (listen.isEmpty()) {
        *error = tr("Masters connect to: type where the masters connect, e.g. tcp://127.0.0.1:5020 (port 0: any free port).");
        return std::nullopt;
    }
    for (const QString &text : listen) {
        const LinkUrl::Result url = LinkUrl::parse(text, LinkUse::Listen);
        if (!url.url) {
            *error = tr("Masters connect to: '%1': %2").arg(text, url.error);
            return std::nullopt;
        }
        setup.listen.append(*url.url);
    }
    for (const QString &text : words(m_routesEdit->text())) {
        const TapRoute::Result route = TapRoute::parse(text);
        if (!route.route) {
            *error = tr("Routes: %1").arg(route.error);
            return std::nullopt;
        }
        setup.settings.routes.append(*route.route);
    }
    if (target.delimited.enabled) {
        *error = tr("The tap forwards Modbus: a target with framing=delimited has no unit ids to route.");
        return std::nullopt;
    }
    TapRoute every; // after the routes: they take their units first
    every.target = target;
    setup.settings.routes.append(every);
    setup.settings.timeoutMs = timeoutMs;
    setup.settings.retries = m_retriesSpin->value();
    setup.settings.noAnswer = TapSettings::NoAnswer(m_noAnswerCombo->currentData().toInt());
    setup.settings.readOnly = m_readOnlyCheck->isChecked();
    setup.settings.refusal = TapSettings::Refusal(m_refusalCombo->currentData().toInt());
    setup.faultsFile = m_faultsEdit->text().trimmed();
    if (!setup.faultsFile.isEmpty()) {
        const FaultRulesLoadResult rules = ProfileLoader::loadFaults(setup.faultsFile);
        if (!rules.ok) {
            *error = tr("Faults: %1").arg(rules.errorText());
            return std::nullopt;
        }
        setup.faults = rules.rules;
    }
    return setup;
}

void TapFields::setSetup(const TapSetup &setup)
{
    QStringList listen;
    for (const LinkUrl &url : setup.listen)
        listen.append(url.toString());
    m_listenEdit->setText(listen.join(QLatin1Char(' ')));
    const QStringList arguments = setup.arguments();
    QStringList routes;
    for (qsizetype i = 0; i + 1 < arguments.size(); ++i) {
        if (arguments.at(i) == QLatin1String("--route"))
            routes.append(arguments.at(i + 1));
    }
    m_routesEdit->setText(routes.join(QLatin1Char(' ')));
    m_readOnlyCheck->setChecked(setup.settings.readOnly);
    m_refusalCombo->setCurrentIndex(qMax(0, m_refusalCombo->findData(int(setup.settings.refusal))));
    m_noAnswerCombo->setCurrentIndex(qMax(0, m_noAnswerCombo->findData(int(setup.settings.noAnswer))));
    m_retriesSpin->setValue(setup.settings.retries);
    m_faultsEdit->setText(setup.faultsFile);
}

namespace {

// The words of `mbscope tap`'s --no-answer and --refuse, as sessions keep them.
QString noAnswerWord(TapSettings::NoAnswer noAnswer)
{
    switch (noAnswer) {
    case TapSettings::NoAnswer::Exception: return QStringLiteral("exception");
    case TapSettings::NoAnswer::Silence: return QStringLiteral("silence");
    case TapSettings::NoAnswer::Auto: break;
    }
    return QStringLiteral("auto");
}

} // namespace

SessionTap TapFields::sessionTap() const
{
    SessionTap tap;
    tap.listen = words(m_listenEdit->text());
    tap.routes = words(m_routesEdit->text());
    tap.readOnly = m_readOnlyCheck->isChecked();
    tap.refuse = TapSettings::Refusal(m_refusalCombo->currentData().toInt()) == TapSettings::Refusal::Silence ? QStringLiteral("silence")
                                                                                                            : QStringLiteral("exception");
    tap.noAnswer = noAnswerWord(TapSettings::NoAnswer(m_noAnswerCombo->currentData().toInt()));
    tap.retries = m_retriesSpin->value();
    tap.faults = m_faultsEdit->text().trimmed();
    return tap;
}

void TapFields::setSessionTap(const SessionTap &tap)
{
    m_listenEdit->setText(tap.listen.join(QLatin1Char(' ')));
    m_routesEdit->setText(tap.routes.join(QLatin1Char(' ')));
    m_readOnlyCheck->setChecked(tap.readOnly);
    const TapSettings::Refusal refusal = tap.refuse == QLatin1String("silence") ? TapSettings::Refusal::Silence : TapSettings::Refusal::Exception;
    m_refusalCombo->setCurrentIndex(qMax(0, m_refusalCombo->findData(int(refusal))));
    TapSettings::NoAnswer noAnswer = TapSettings::NoAnswer::Auto;
    for (TapSettings::NoAnswer n : {TapSettings::NoAnswer::Exception, TapSettings::NoAnswer::Silence}) {
        if (tap.noAnswer == noAnswerWord(n))
            noAnswer = n;
    }
    m_noAnswerCombo->setCurrentIndex(qMax(0, m_noAnswerCombo->findData(int(noAnswer))));
    m_retriesSpin->setValue(tap.retries);
    m_faultsEdit->setText(tap.faults);
}

void TapFields::remember() const
{
    QSettings settings;
    settings.setValue(kListenKey, m_listenEdit->text().trimmed());
    settings.setValue(kRoutesKey, m_routesEdit->text().trimmed());
    settings.setValue(kReadOnlyKey, m_readOnlyCheck->isChecked());
    settings.setValue(kRefusalKey, m_refusalCombo->currentData().toInt());
    settings.setValue(kNoAnswerKey, m_noAnswerCombo->currentData().toInt());
    settings.setValue(kRetriesKey, m_retriesSpin->value());
    settings.setValue(kFaultsKey, m_faultsEdit->text().trimmed());
}

void TapFields::setRunning(bool running)
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_listenEdit, m_routesEdit, m_readOnlyCheck, m_noAnswerCombo, m_retriesSpin, m_faultsEdit})
        w->setEnabled(!running);
    m_refusalCombo->setEnabled(!running && m_readOnlyCheck->isChecked());
    if (running) {
        showCounters({}, 0);
        m_countersLabel->show();
    }
}

void TapFields::showCounters(const TapCounters &c, int waiting)
{
    const QLocale locale;
    QString text = tr("Tap: %1 requests from masters, %2 forwarded: %3 answered, %4 exceptions from devices, %5 without "
                      "answer, %6 link errors, %7 damaged; %8 without route, %9 writes refused; %10 waiting")
                       .arg(locale.toString(c.requests), locale.toString(c.forwarded), locale.toString(c.answered),
                            locale.toString(c.exceptions), locale.toString(c.noAnswer), locale.toString(c.linkErrors),
                            locale.toString(c.damaged), locale.toString(c.noRoute), locale.toString(c.refusedWrites))
                       .arg(waiting);
    if (c.deviceLatencyCount > 0)
        text += tr("; devices answered in %1 on average").arg(formatDuration(qint64(c.deviceLatencyNsSum / c.deviceLatencyCount)));
    m_countersLabel->setText(text);
}

QString TapFields::countersText() const
{
    return m_countersLabel->text();
}

} // namespace mbscope
