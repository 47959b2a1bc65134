#include "trafficmonitor.h"

#include "common/lastfolder.h"

#include "common/coretext.h"

#include "common/severitystyle.h"
#include "trafficmodel.h"
#include "common/trafficstyle.h"

#include "protocol/functioncode.h"
#include "protocol/hexformat.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QStandardPaths>
#include <QtGui/QAction>
#include <QtGui/QKeySequence>
#include <QtGui/QShortcut>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

// Verdict filter choices beyond single verdicts.
constexpr int kAnyVerdict = -1;
constexpr int kProblemsOnly = -2;

// Column widths in digits of the table's font: fixed so a million rows never need measuring.
struct ColumnWidth {
    TrafficModel::Column column;
    int chars;
};
constexpr ColumnWidth kColumnWidths[] = {
    {TrafficModel::NumberColumn, 7},  {TrafficModel::TimeColumn, 11},    {TrafficModel::DirectionColumn, 6},
    {TrafficModel::LinkColumn, 22},   {TrafficModel::UnitColumn, 4},     {TrafficModel::FunctionColumn, 30},
    {TrafficModel::LengthColumn, 6},  {TrafficModel::LatencyColumn, 10}, {TrafficModel::VerdictColumn, 11},
};

} // namespace

TrafficMonitor::TrafficMonitor(QWidget *parent)
    : QWidget(parent)
    , m_model(new TrafficModel(this))
{
    // The oldest frames beyond the list's memory go to disk, in the cache folder, and stay listed.
    m_model->setArchiveFolder(QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/traffic-list"));
    buildUi();
    connect(m_model, &TrafficModel::countsChanged, this, &TrafficMonitor::updateStatus);
    connect(m_model, &QAbstractItemModel::rowsAboutToBeInserted, this, &TrafficMonitor::onRowsAboutToBeInserted);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &TrafficMonitor::onRowsInserted);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &TrafficMonitor::onCurrentChanged);
    updateStatus();
}

void TrafficMonitor::buildUi()
{
    m_unitSpin = new QSpinBox(this);
    m_unitSpin->setObjectName(QStringLiteral("unitFilter"));
    m_unitSpin->setRange(-1, 255);
    m_unitSpin->setValue(-1);
    m_unitSpin->setSpecialValueText(tr("any"));
    m_unitSpin->setToolTip(tr("Show only frames of this unit id"));

    m_functionCombo = new QComboBox(this);
    m_functionCombo->setObjectName(QStringLiteral("functionFilter"));
    m_functionCombo->addItem(tr("any"), -1);
    for (int code = 1; code < 0x80; ++code) {
        if (functionKind(quint8(code)) == FunctionKind::Public)
            m_functionCombo->addItem(hexByte(quint8(code)) + QLatin1Char(' ') + fieldText(functionName(quint8(code))), code);
    }
    m_functionCombo->setToolTip(tr("Show only frames of this function code (its exception responses included)"));

    m_directionCombo = new QComboBox(this);
    m_directionCombo->setObjectName(QStringLiteral("directionFilter"));
    m_directionCombo->addItem(tr("both"), -1);
    m_directionCombo->addItem(TrafficStyle::directionText(TrafficDirection::Out), int(TrafficDirection::Out));
    m_directionCombo->addItem(TrafficStyle::directionText(TrafficDirection::In), int(TrafficDirection::In));

    m_verdictCombo = new QComboBox(this);
    m_verdictCombo->setObjectName(QStringLiteral("verdictFilter"));
    m_verdictCombo->addItem(tr("any"), kAnyVerdict);
    m_verdictCombo->addItem(tr("problems only"), kProblemsOnly);
    for (int v = 0; v < kTrafficVerdictCount; ++v)
        m_verdictCombo->addItem(TrafficStyle::verdictText(TrafficVerdict(v)), v);

    m_pauseButton = new QToolButton(this);
    m_pauseButton->setObjectName(QStringLiteral("pauseButton"));
    m_pauseButton->setText(tr("Pause"));
    m_pauseButton->setCheckable(true);
    m_pauseButton->setToolTip(tr("Hold new frames back from the list; nothing is dropped, they appear on resume"));
    m_clearButton = new QToolButton(this);
    m_clearButton->setObjectName(QStringLiteral("clearButton"));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Empty the list (the connection's traffic journal keeps every frame, unless recording "
                                 "is turned off in Preferences)"));

    m_saveAction = new QAction(tr("Save &Traffic As\u2026"), this);
    m_saveAction->setObjectName(QStringLiteral("saveTrafficAction"));
    m_saveAction->setToolTip(tr("Save the frames listed (all, or what the filter shows) as a traffic journal, a "
                                "Wireshark capture (pcapng, pcap), CSV or JSON lines"));
    auto *saveButton = new QToolButton(this);
    saveButton->setObjectName(QStringLiteral("saveTrafficButton"));
    saveButton->setDefaultAction(m_saveAction);
    saveButton->setText(tr("Save\u2026"));

    m_searchEdit = new QLineEdit(this);
    m_searchEdit->setObjectName(QStringLiteral("searchEdit"));
    m_searchEdit->setClearButtonEnabled(true);
    m_searchEdit->setPlaceholderText(tr("Find: hex bytes or text (Enter, F3)"));
    auto *previous = new QToolButton(this);
    previous->setText(QStringLiteral("\u25B2"));
    previous->setToolTip(tr("Find previous (Shift+F3)"));
    auto *next = new QToolButton(this);
    next->setText(QStringLiteral("\u25BC"));
    next->setToolTip(tr("Find next (F3)"));

    // Narrow windows (1024 px) keep the whole filter row: the combos and the search give way.
    for (QComboBox *combo : {m_functionCombo, m_directionCombo, m_verdictCombo}) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(6);
    }
    m_searchEdit->setMinimumWidth(70);
    auto *filters = new QHBoxLayout;
    const auto labelled = [this, filters](const QString &text, QWidget *w) {
        auto *label = new QLabel(text, this);
        label->setBuddy(w);
        filters->addWidget(label);
        filters->addWidget(w);
    };
    labelled(tr("Unit:"), m_unitSpin);
    labelled(tr("Function:"), m_functionCombo);
    labelled(tr("Direction:"), m_directionCombo);
    labelled(tr("Verdict:"), m_verdictCombo);
    filters->addSpacing(4);
    filters->addWidget(m_pauseButton);
    filters->addWidget(m_clearButton);
    filters->addWidget(saveButton);
    filters->addSpacing(4);
    filters->addWidget(m_searchEdit, 1);
    filters->addWidget(previous);
    filters->addWidget(next);

    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("trafficView"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setShowGrid(false);
    m_view->setWordWrap(false);
    m_view->setAlternatingRowColors(true);
    m_view->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    // Every row is one line: fixed heights mean a million rows cost no measuring.
    QHeaderView *rows = m_view->verticalHeader();
    rows->hide();
    rows->setSectionResizeMode(QHeaderView::Fixed);
    rows->setDefaultSectionSize(m_view->fontMetrics().height() + 4);
    QHeaderView *columns = m_view->horizontalHeader();
    columns->setSectionResizeMode(QHeaderView::Interactive);
    columns->setStretchLastSection(true);
    columns->setHighlightSections(false);
    // Digits are wider than the average character: a seven-digit frame number must not elide.
    const int charWidth = m_view->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    constexpr int kCellPadding = 12;
    for (const ColumnWidth &w : kColumnWidths)
        m_view->setColumnWidth(w.column, w.chars * charWidth + kCellPadding);

    m_statusLabel = new QLabel(this);
    m_statusLabel->setObjectName(QStringLiteral("statusLabel"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(filters);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_statusLabel);

    connect(m_unitSpin, &QSpinBox::valueChanged, this, &TrafficMonitor::applyFilter);
    connect(m_functionCombo, &QComboBox::currentIndexChanged, this, &TrafficMonitor::applyFilter);
    connect(m_directionCombo, &QComboBox::currentIndexChanged, this, &TrafficMonitor::applyFilter);
    connect(m_verdictCombo, &QComboBox::currentIndexChanged, this, &TrafficMonitor::applyFilter);
    connect(m_pauseButton, &QToolButton::toggled, this, &TrafficMonitor::setPaused);
    connect(m_clearButton, &QToolButton::clicked, this, &TrafficMonitor::clear);
    connect(m_saveAction, &QAction::triggered, this, &TrafficMonitor::saveTrafficAs);
    connect(m_searchEdit, &QLineEdit::returnPressed, this, &TrafficMonitor::findNext);
    connect(next, &QToolButton::clicked, this, &TrafficMonitor::findNext);
    connect(previous, &QToolButton::clicked, this, &TrafficMonitor::findPrevious);

    const auto shortcut = [this](const QKeySequence &keys, void (TrafficMonitor::*slot)()) {
        auto *s = new QShortcut(keys, this);
        s->setContext(Qt::WidgetWithChildrenShortcut);
        connect(s, &QShortcut::activated, this, slot);
    };
    shortcut(QKeySequence::Find, &TrafficMonitor::focusSearch);
    shortcut(QKeySequence::FindNext, &TrafficMonitor::findNext);
    shortcut(QKeySequence::FindPrevious, &TrafficMonitor::findPrevious);
}

void TrafficMonitor::saveTrafficAs()
{
    if (m_model->frameCount() == 0) {
        m_findMessage = tr("nothing to save: the list is empty");
        updateStatus();
        return;
    }
    const QLocale locale;
    bool shownOnly = false;
    const qsizetype listed = m_model->frameCount() - m_model->heldCount();
    if (m_model->rowCount() != listed) {
        QMessageBox ask(QMessageBox::Question, tr("Save Traffic"),
                        tr("The filter shows %1 of the %2 frames listed. Save which?")
                            .arg(locale.toString(m_model->rowCount()), locale.toString(qlonglong(m_model->frameCount()))),
                        QMessageBox::Cancel, this);
        ask.setObjectName(QStringLiteral("saveWhichFrames"));
        QPushButton *all = ask.addButton(tr("&All frames"), QMessageBox::AcceptRole);
        QPushButton *shown = ask.addButton(tr("&Shown frames"), QMessageBox::AcceptRole);
        ask.setDefaultButton(all);
        ask.exec();
        if (ask.clickedButton() != all && ask.clickedButton() != shown)
            return;
        shownOnly = ask.clickedButton() == shown;
    }
    QFileDialog dialog(this, tr("Save Traffic As"));
    dialog.setObjectName(QStringLiteral("saveTrafficDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setFileMode(QFileDialog::AnyFile);
    dialog.setNameFilters(TrafficSaver::nameFilters());
    if (m_lastSaveDirectory.isEmpty())
        m_lastSaveDirectory = LastFolder::folder();
    dialog.setDirectory(m_lastSaveDirectory);
    dialog.selectFile(QStringLiteral("traffic") + trafficformat::suffix(TrafficFormat::Journal));
    connect(&dialog, &QFileDialog::filterSelected, &dialog, [&dialog](const QString &filter) {
        // The name follows the format picked, so the file is found again under that filter.
        const QStringList picked = dialog.selectedFiles();
        if (picked.isEmpty())
            return;
        QString name = QFileInfo(picked.constFirst()).fileName();
        const TrafficFormat was = TrafficSaver::formatFor(name);
        if (name.endsWith(trafficformat::suffix(was), Qt::CaseInsensitive))
            name.chop(trafficformat::suffix(was).size());
        dialog.selectFile(name + trafficformat::suffix(TrafficSaver::formatOfFilter(filter)));
    });
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    QString path = dialog.selectedFiles().constFirst();
    // A name typed with a format's ending ("bench.pcapng") is saved in that format, whatever the
    // filter says; a name without one gets the filter's format and its ending, so the file shows
    // under the same filter later.
    const std::optional<TrafficFormat> typed = trafficformat::ofEnding(path);
    const TrafficFormat format = typed.value_or(TrafficSaver::formatOfFilter(dialog.selectedNameFilter()));
    if (!typed)
        path += trafficformat::suffix(format);
    m_lastSaveDirectory = QFileInfo(path).absolutePath();
    LastFolder::remember(path);
    const TrafficSaver::Result result = saveTo(path, format, shownOnly);
    auto *box = new QMessageBox(result.ok ? QMessageBox::Information : QMessageBox::Warning, tr("Save Traffic"),
                                result.summary(format, path), QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("trafficSavedMessage"));
    box->setTextInteractionFlags(Qt::TextSelectableByMouse);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

TrafficSaver::Result TrafficMonitor::saveTo(const QString &path, TrafficFormat format, bool shownOnly)
{
    const QStringList &links = m_model->links().names();
    const TrafficSaver::Result result =
        TrafficSaver::save(*m_model, shownOnly, path, format, links.isEmpty() ? QString() : links.constLast());
    m_findMessage = result.summary(format, path);
    updateStatus();
    Q_EMIT saved(m_findMessage, result.ok);
    return result;
}

void TrafficMonitor::appendFrames(const QList<TrafficFrame> &frames)
{
    m_model->appendFrames(frames);
}

void TrafficMonitor::appendTransactions(const QList<Transaction> &transactions)
{
    m_model->appendTransactions(transactions);
}

void TrafficMonitor::appendRecordedTransactions(const QList<Transaction> &transactions)
{
    m_model->appendRecordedTransactions(transactions);
}

void TrafficMonitor::appendLinkFrames(const QList<TrafficFrame> &frames, const QString &link)
{
    m_model->appendLinkFrames(frames, link);
}

void TrafficMonitor::appendNamedFrames(const QList<TrafficFrame> &frames, const QStringList &links)
{
    m_model->appendNamedFrames(frames, links);
}

bool TrafficMonitor::isPaused() const
{
    return m_model->isPaused();
}

void TrafficMonitor::setPaused(bool paused)
{
    m_model->setPaused(paused);
    const QSignalBlocker block(m_pauseButton);
    m_pauseButton->setChecked(paused);
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
}

void TrafficMonitor::clear()
{
    m_findMessage.clear();
    m_model->clear();
    m_follow = true;
}

int TrafficMonitor::currentRow() const
{
    const QModelIndex current = m_view->currentIndex();
    return current.isValid() ? current.row() : -1;
}

void TrafficMonitor::selectRow(int row)
{
    if (row < 0 || row >= m_model->rowCount()) {
        m_view->selectionModel()->clear();
        return;
    }
    const QModelIndex index = m_model->index(row, 0);
    m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_view->scrollTo(index);
}

void TrafficMonitor::applyFilter()
{
    TrafficFilter filter;
    filter.unit = m_unitSpin->value();
    filter.function = m_functionCombo->currentData().toInt();
    filter.direction = m_directionCombo->currentData().toInt();
    const int verdict = m_verdictCombo->currentData().toInt();
    if (verdict == kProblemsOnly) {
        filter.verdicts = 0;
        for (int v = 0; v < kTrafficVerdictCount; ++v)
            filter.setVerdict(TrafficVerdict(v), TrafficStyle::severity(TrafficVerdict(v)) >= Severity::Warning);
    } else if (verdict >= 0) {
        filter.verdicts = 0;
        filter.setVerdict(TrafficVerdict(verdict), true);
    }
    // The selected frame stays selected when the new filter shows it.
    const qsizetype selected = m_model->storeRow(currentRow());
    m_model->setFilter(filter);
    m_findMessage.clear();
    const int row = m_model->rowOfStoreRow(selected);
    if (row >= 0)
        selectRow(row);
    else if (m_follow)
        m_view->scrollToBottom();
    updateStatus();
}

void TrafficMonitor::onCurrentChanged()
{
    const int row = currentRow();
    if (row >= 0)
        Q_EMIT frameSelected(m_model->exchangeAt(row));
}

void TrafficMonitor::onRowsAboutToBeInserted()
{
    const QScrollBar *bar = m_view->verticalScrollBar();
    m_follow = bar->value() >= bar->maximum();
}

void TrafficMonitor::onRowsInserted()
{
    if (m_follow)
        m_view->scrollToBottom();
}

void TrafficMonitor::focusSearch()
{
    m_searchEdit->setFocus(Qt::ShortcutFocusReason);
    m_searchEdit->selectAll();
}

void TrafficMonitor::findNext()
{
    find(true);
}

void TrafficMonitor::findPrevious()
{
    find(false);
}

void TrafficMonitor::find(bool forward)
{
    const QString query = m_searchEdit->text();
    if (query.trimmed().isEmpty()) {
        focusSearch();
        return;
    }
    const int row = m_model->findNext(query, currentRow(), forward);
    if (row < 0) {
        m_findMessage = tr("No frame shown matches \u201C%1\u201D").arg(query.trimmed());
    } else {
        m_findMessage.clear();
        m_follow = false;
        selectRow(row);
    }
    updateStatus();
}

void TrafficMonitor::updateStatus()
{
    const QLocale locale;
    QString text = tr("%1 frames").arg(locale.toString(qlonglong(m_model->frameCount())));
    if (m_model->rowCount() != m_model->frameCount() - m_model->heldCount())
        text += tr(", %1 shown").arg(locale.toString(m_model->rowCount()));
    if (m_model->isPaused())
        text += tr(" \u00B7 paused: %1 new frames held").arg(locale.toString(qlonglong(m_model->heldCount())));
    if (m_model->droppedCount() > 0)
        text += tr(" \u00B7 %1 oldest dropped from the list").arg(locale.toString(qulonglong(m_model->droppedCount())));
    if (!m_model->archiveProblem().isEmpty())
        text += tr(" \u00B7 older frames are no longer kept on disk: %1").arg(m_model->archiveProblem());
    SeverityStyle::setTextColour(m_statusLabel, m_findMessage.isEmpty() ? Severity::Ok : Severity::Warning);
    if (!m_findMessage.isEmpty())
        text += QStringLiteral(" \u00B7 ") + m_findMessage;
    m_statusLabel->setText(text);
}

} // namespace mbscope
