#include "replaypanel.h"

#include "common/lastfolder.h"

#include "replaycontroller.h"
#include "replaydifferencesmodel.h"
#include "replayserver.h"

#include "capture/captureports.h"
#include "replay/replayscript.h"

#include <QtCore/QTimer>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

ReplayPanel::ReplayPanel(ReplayController *controller, QWidget *parent)
    : QWidget(parent), m_controller(controller)
{
    m_chooser = [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open a capture or a session"), LastFolder::start(),
                                                          tr("Captures and sessions (*.pcap *.pcapng *.cap *.json *.journal);;All files (*)"));
        LastFolder::remember(path);
        return path;
    };
    m_writesAsker = [](QMessageBox &question) { return QMessageBox::StandardButton(question.exec()); };
    buildUi();
    connect(m_controller, &ReplayController::busyChanged, this, &ReplayPanel::updateState);
    connect(m_controller, &ReplayController::sourceOpened, this, [this](const QString &summary) {
        m_source->setText(m_controller->sourcePath());
        m_analysis->setText(summary);
        // The ports the capture was read with, also when the controller was told them directly.
        m_mbapPorts->setText(CapturePorts::format(m_controller->captureOptions().mbapPorts));
        m_rtuPorts->setText(CapturePorts::format(m_controller->captureOptions().rtuPorts));
        showMessage(QString(), false);
    });
    connect(m_controller, &ReplayController::sourceFailed, this, [this](const QString &message) { showMessage(message, true); });
    connect(m_controller, &ReplayController::replayStarted, this, [this] {
        m_counts->setText(tr("Replaying the recorded requests to the target (%1 in all)…").arg(m_controller->script()->size()));
    });
    connect(m_controller, &ReplayController::outcomeReplayed, this,
            [this] { m_counts->setText(m_controller->differences()->countsText()); });
    connect(m_controller, &ReplayController::replayFinished, this, [this](const QString &summary) { m_counts->setText(summary); });
    m_servingTimer = new QTimer(this);
    m_servingTimer->setInterval(1000);
    connect(m_servingTimer, &QTimer::timeout, this, [this] { m_serving->setText(m_controller->servingText()); });
    updateState();
}

void ReplayPanel::buildUi()
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    auto *sourceRow = new QHBoxLayout;
    m_openButton = new QPushButton(tr("Open capture…"), this);
    m_openButton->setToolTip(tr("A pcap or pcapng capture, a traffic journal, or a session document with captured traffic"));
    connect(m_openButton, &QPushButton::clicked, this, &ReplayPanel::chooseAndOpen);
    m_source = new QLabel(tr("No recording opened."), this);
    m_source->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_mbapPorts = new QLineEdit(CapturePorts::format(CaptureOptions{}.mbapPorts), this);
    m_mbapPorts->setToolTip(tr("Server ports carrying Modbus TCP or Modbus UDP in a capture, separated by commas"));
    m_mbapPorts->setMaximumWidth(110);
    m_rtuPorts = new QLineEdit(this);
    m_rtuPorts->setPlaceholderText(tr("e.g. 4001"));
    m_rtuPorts->setToolTip(tr("Server ports carrying RTU frames over TCP or UDP in a capture (a serial device server)"));
    m_rtuPorts->setMaximumWidth(110);
    sourceRow->addWidget(m_openButton);
    sourceRow->addWidget(m_source, 1);
    sourceRow->addWidget(new QLabel(tr("Modbus TCP ports"), this));
    sourceRow->addWidget(m_mbapPorts);
    sourceRow->addWidget(new QLabel(tr("RTU ports"), this));
    sourceRow->addWidget(m_rtuPorts);
    layout->addLayout(sourceRow);

    m_analysis = new QLabel(this);
    m_analysis->setWordWrap(true);
    m_analysis->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_analysis);

    auto *replayRow = new QHBoxLayout;
    m_speed = new QComboBox(this);
    m_speed->addItem(tr("As recorded"), 1.0);
    m_speed->addItem(tr("2 times faster"), 2.0);
    m_speed->addItem(tr("10 times faster"), 10.0);
    m_speed->addItem(tr("Back to back"), 0.0);
    m_replayButton = new QPushButton(tr("Replay to the target"), this);
    m_replayButton->setToolTip(tr("Send the recorded requests to the connected device and compare each answer with the recorded one"));
    connect(m_replayButton, &QPushButton::clicked, this, &ReplayPanel::replay);
    m_stopButton = new QPushButton(tr("Stop"), this);
    connect(m_stopButton, &QPushButton::clicked, m_controller, &ReplayController::stopReplay);
    m_showMatches = new QCheckBox(tr("Show matching answers"), this);
    connect(m_showMatches, &QCheckBox::toggled, m_controller->differences(), &ReplayDifferencesModel::setShowMatches);
    replayRow->addWidget(new QLabel(tr("Speed"), this));
    replayRow->addWidget(m_speed);
    replayRow->addWidget(m_replayButton);
    replayRow->addWidget(m_stopButton);
    replayRow->addStretch(1);
    replayRow->addWidget(m_showMatches);
    layout->addLayout(replayRow);

    m_counts = new QLabel(this);
    m_counts->setWordWrap(true);
    m_counts->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_counts);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("replayDifferences"));
    m_table->setModel(m_controller->differences());
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(ReplayDifferencesModel::DifferencesColumn, QHeaderView::Stretch);
    m_table->setColumnWidth(ReplayDifferencesModel::IndexColumn, 40);
    m_table->setColumnWidth(ReplayDifferencesModel::RequestColumn, 190);
    m_table->setColumnWidth(ReplayDifferencesModel::RecordedColumn, 190);
    m_table->setColumnWidth(ReplayDifferencesModel::NowColumn, 190);
    m_table->setColumnWidth(ReplayDifferencesModel::KindColumn, 90);
    layout->addWidget(m_table, 1);

    auto *serveRow = new QHBoxLayout;
    m_serveUrl = new QLineEdit(QStringLiteral("tcp://127.0.0.1:1502"), this);
    m_serveUrl->setToolTip(tr("Where the recording answers as a device: tcp://, rtu-tcp://, udp://, rtu://… (port 0: any free port)"));
    m_unrecorded = new QComboBox(this);
    m_unrecorded->addItem(tr("Answer other requests with exception 0B"), int(ReplayResponder::Unrecorded::Exception0B));
    m_unrecorded->addItem(tr("Leave other requests unanswered"), int(ReplayResponder::Unrecorded::Ignore));
    m_serveButton = new QPushButton(tr("Serve"), this);
    m_serveButton->setToolTip(tr("Answer with the recorded answers on this endpoint, matched by unit and request"));
    connect(m_serveButton, &QPushButton::clicked, this, &ReplayPanel::toggleServing);
    serveRow->addWidget(new QLabel(tr("Serve on"), this));
    serveRow->addWidget(m_serveUrl, 1);
    serveRow->addWidget(m_unrecorded);
    serveRow->addWidget(m_serveButton);
    layout->addLayout(serveRow);
    m_serving = new QLabel(this);
    m_serving->setWordWrap(true);
    layout->addWidget(m_serving);

    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setObjectName(QStringLiteral("replayMessage"));
    m_message->hide();
    layout->addWidget(m_message);
}

void ReplayPanel::chooseAndOpen()
{
    const QString path = m_chooser ? m_chooser() : QString();
    if (!path.isEmpty())
        open(path);
}

bool ReplayPanel::open(const QString &source)
{
    CaptureOptions options = m_controller->captureOptions();
    QString error;
    if (!CapturePorts::parse(m_mbapPorts->text(), &options.mbapPorts, &error)) {
        showMessage(tr("Modbus TCP ports: %1").arg(error), true);
        return false;
    }
    options.rtuPorts.clear();
    if (!m_rtuPorts->text().trimmed().isEmpty() && !CapturePorts::parse(m_rtuPorts->text(), &options.rtuPorts, &error)) {
        showMessage(tr("RTU ports: %1").arg(error), true);
        return false;
    }
    m_controller->setCaptureOptions(options);
    showMessage(QString(), false);
    if (!m_controller->openSource(source))
        return false;
    m_source->setText(tr("Reading %1…").arg(source));
    return true;
}

void ReplayPanel::replay()
{
    bool sendWrites = false;
    const QList<RecordedWrite> writes = m_controller->script() ? m_controller->script()->writes() : QList<RecordedWrite>{};
    if (!writes.isEmpty() && !m_controller->isReplaying()) {
        QMessageBox question(QMessageBox::Warning, tr("Send the recorded writes?"),
                             tr("The recording holds %n write(s) to the device: %1.", nullptr, int(writes.size()))
                                 .arg(RecordedWrite::placesText(writes)),
                             QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel, this);
        question.setInformativeText(tr("Sending them changes the device again as they changed it when recorded (its outputs, "
                                       "its settings). Without them the other requests are replayed and the writes are listed "
                                       "as not sent."));
        question.button(QMessageBox::Yes)->setText(tr("Send the writes"));
        question.button(QMessageBox::No)->setText(tr("Replay without the writes"));
        question.setDefaultButton(QMessageBox::No);
        question.setEscapeButton(QMessageBox::Cancel);
        const QMessageBox::StandardButton answer = m_writesAsker(question);
        if (answer != QMessageBox::Yes && answer != QMessageBox::No) {
            showMessage(tr("Replay not started."), false);
            return;
        }
        sendWrites = answer == QMessageBox::Yes;
    }
    QString error;
    if (!m_controller->startReplay(speed(), sendWrites, &error))
        showMessage(error, true);
    else
        showMessage(QString(), false);
}

void ReplayPanel::toggleServing()
{
    if (m_controller->server()->isServing()) {
        m_controller->stopServing();
        m_serving->setText(tr("Stopped serving."));
        return;
    }
    QString error;
    const auto policy = ReplayResponder::Unrecorded(m_unrecorded->currentData().toInt());
    if (!m_controller->startServing(m_serveUrl->text().trimmed(), policy, speed(), &error)) {
        showMessage(error, true);
        return;
    }
    showMessage(QString(), false);
    m_serving->setText(m_controller->servingText());
}

double ReplayPanel::speed() const
{
    return m_speed->currentData().toDouble();
}

QString ReplayPanel::message() const
{
    return m_message->isVisible() ? m_message->text() : QString();
}

void ReplayPanel::updateState()
{
    const bool replaying = m_controller->isReplaying();
    const bool loading = m_controller->isLoading();
    const bool serving = m_controller->server()->isServing();
    m_openButton->setEnabled(!replaying && !loading);
    m_replayButton->setEnabled(m_controller->hasSource() && !replaying && !loading);
    m_stopButton->setEnabled(replaying);
    m_serveButton->setEnabled(serving || (m_controller->hasSource() && !loading));
    m_serveButton->setText(serving ? tr("Stop serving") : tr("Serve"));
    m_serveUrl->setEnabled(!serving);
    m_unrecorded->setEnabled(!serving);
    if (serving)
        m_servingTimer->start();
    else
        m_servingTimer->stop();
}

void ReplayPanel::showMessage(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b02020;") : QString());
    m_message->setVisible(!text.isEmpty());
}

} // namespace mbscope
