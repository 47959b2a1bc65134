#include "planpanel.h"

#include "common/lastfolder.h"

#include "plancontroller.h"
#include "planresultmodel.h"

#include "session/planresult.h"

#include <QtWidgets/QFileDialog>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

PlanPanel::PlanPanel(PlanController *controller, DocumentSource document, QWidget *parent)
    : QWidget(parent), m_controller(controller), m_document(std::move(document))
{
    m_chooser = [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export the results as JUnit XML"),
                                                          LastFolder::start(QStringLiteral("results.xml")),
                                                          tr("JUnit XML (*.xml);;All files (*)"));
        LastFolder::remember(path);
        return path;
    };
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto *row = new QHBoxLayout;
    m_runButton = new QPushButton(tr("Run plan"), this);
    m_runButton->setToolTip(tr("Run the session's test plan against the connected device (or the session's target)"));
    connect(m_runButton, &QPushButton::clicked, this, &PlanPanel::run);
    m_stopButton = new QPushButton(tr("Stop"), this);
    connect(m_stopButton, &QPushButton::clicked, m_controller, &PlanController::stop);
    m_exportButton = new QPushButton(tr("Export JUnit XML…"), this);
    connect(m_exportButton, &QPushButton::clicked, this, &PlanPanel::exportJUnit);
    row->addWidget(m_runButton);
    row->addWidget(m_stopButton);
    row->addStretch(1);
    row->addWidget(m_exportButton);
    layout->addLayout(row);

    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("planResults"));
    m_table->setModel(m_controller->results());
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->setColumnWidth(PlanResultModel::OutcomeColumn, 60);
    m_table->setColumnWidth(PlanResultModel::StepColumn, 180);
    m_table->setColumnWidth(PlanResultModel::ExpectedColumn, 240);
    m_table->setColumnWidth(PlanResultModel::CameColumn, 300);
    m_table->horizontalHeader()->setSectionResizeMode(PlanResultModel::WhyColumn, QHeaderView::Stretch);
    m_table->horizontalHeader()->setStretchLastSection(false);
    layout->addWidget(m_table, 1);

    connect(m_controller, &PlanController::started, this, [this](const QString &plan, const QString &target) {
        setSummary(tr("Running %1 against %2…").arg(plan.isEmpty() ? tr("the plan") : plan, target), false);
    });
    connect(m_controller, &PlanController::stepFinished, this, [this] { m_table->scrollToBottom(); });
    connect(m_controller, &PlanController::finished, this, [this](const QString &summary, bool passed) { setSummary(summary, !passed); });
    connect(m_controller, &PlanController::runningChanged, this, &PlanPanel::updateState);
    updateState();
    showDocumentHint();
}

void PlanPanel::showDocumentHint()
{
    if (m_controller->isRunning() || m_controller->lastResult().has_value())
        return;
    const SessionDocument document = m_document();
    if (document.plan.empty()) {
        m_summary->setText(tr("This session has no test plan. Open a session with one (File > Open), then run it."));
    } else {
        const QString name = document.name.isEmpty() ? tr("The session's plan") : tr("The plan of %1").arg(document.name);
        m_summary->setText(tr("%1 has %n step(s). Press Run plan to run it against the connected device.", nullptr,
                              planStepCount(document.plan))
                               .arg(name));
    }
    m_summary->setStyleSheet(QString());
}

void PlanPanel::run()
{
    QString error;
    if (!m_controller->run(m_document(), &error))
        setSummary(error, true);
}

void PlanPanel::exportJUnit()
{
    const QString path = m_chooser ? m_chooser() : QString();
    if (path.isEmpty())
        return;
    QString error;
    if (!m_controller->exportJUnit(path, &error))
        setSummary(error, true);
    else
        setSummary(tr("%1 JUnit XML written to %2.").arg(m_controller->summary(), path), !m_controller->lastResult()->passed());
}

QString PlanPanel::summaryText() const
{
    return m_summary->text();
}

void PlanPanel::setSummary(const QString &text, bool problem)
{
    m_summary->setText(text);
    m_summary->setStyleSheet(problem ? QStringLiteral("color: #b02020; font-weight: bold;")
                                     : QStringLiteral("color: #1e7b34; font-weight: bold;"));
}

void PlanPanel::updateState()
{
    const bool running = m_controller->isRunning();
    m_runButton->setEnabled(!running);
    m_stopButton->setEnabled(running);
    m_exportButton->setEnabled(!running && m_controller->lastResult().has_value());
}

} // namespace mbscope
