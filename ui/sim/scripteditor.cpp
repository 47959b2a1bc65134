#include "scripteditor.h"

#include "scripthighlighter.h"

#include "common/severitystyle.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDir>
#include <QtCore/QEvent>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QRegularExpression>
#include <QtGui/QFontDatabase>
#include <QtGui/QFontMetrics>
#include <QtGui/QKeySequence>
#include <QtGui/QShortcut>
#include <QtGui/QTextBlock>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

bool insideProgram(const QString &path)
{
    return path.startsWith(QLatin1Char(':')) || path.startsWith(QLatin1String("qrc:"));
}

} // namespace

ScriptEditor::ScriptEditor(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *row = new QHBoxLayout;
    m_choice = new QComboBox(this);
    m_choice->setObjectName(QStringLiteral("simScriptChoice"));
    m_choice->setToolTip(tr("The script shown in the editor"));
    row->addWidget(m_choice, 1);
    m_save = new QPushButton(tr("&Save script"), this);
    m_save->setObjectName(QStringLiteral("simSaveScript"));
    m_save->setToolTip(tr("Writes the script to its file (Ctrl+S); the simulator loads it again at once."));
    row->addWidget(m_save);
    layout->addLayout(row);
    m_edit = new QPlainTextEdit(this);
    m_edit->setObjectName(QStringLiteral("simScriptEditor"));
    m_edit->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_edit->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_edit->setTabStopDistance(4 * QFontMetricsF(m_edit->font()).horizontalAdvance(QLatin1Char(' ')));
    m_highlighter = new ScriptHighlighter(m_edit->document());
    layout->addWidget(m_edit, 1);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("simScriptStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);

    auto *saveKey = new QShortcut(QKeySequence::Save, this, nullptr, nullptr, Qt::WidgetWithChildrenShortcut);
    connect(saveKey, &QShortcut::activated, this, &ScriptEditor::save);
    connect(m_save, &QPushButton::clicked, this, &ScriptEditor::save);
    connect(m_choice, &QComboBox::currentIndexChanged, this, &ScriptEditor::show);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &ScriptEditor::onFileChanged);
    connect(m_edit->document(), &QTextDocument::modificationChanged, this, [this](bool modified) {
        m_save->setEnabled(modified && m_current >= 0 && !insideProgram(path()));
    });
    setHost(nullptr);
}

void ScriptEditor::setHost(SimulatorHost *host)
{
    m_host = host;
    m_list.clear();
    if (host) {
        for (const UnitProfile &unit : host->profile().units) {
            if (!unit.script.isEmpty())
                m_list.append({QStringLiteral("unit %1: %2").arg(unit.id).arg(unit.script.name), unit.script.name, unit.script.path});
        }
        const ScriptSettings &line = host->profile().delimited.script;
        if (!line.isEmpty())
            m_list.append({QStringLiteral("delimited: %1").arg(line.name), line.name, line.path});
    }
    const QSignalBlocker block(m_choice);
    m_choice->clear();
    for (const Script &s : std::as_const(m_list))
        m_choice->addItem(s.who);
    m_choice->setEnabled(m_list.size() > 1);
    show(m_list.isEmpty() ? -1 : 0);
}

QString ScriptEditor::path() const
{
    return m_current >= 0 ? m_list.at(m_current).path : QString();
}

void ScriptEditor::show(int index)
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    m_current = index >= 0 && index < m_list.size() ? index : -1;
    m_errorLine = 0;
    if (m_current < 0) {
        m_edit->clear();
        m_edit->setReadOnly(true);
        m_edit->setPlaceholderText(tr("No script: the selected simulator's profile names none."));
        m_save->setEnabled(false);
        setStatus(QString(), false);
        return;
    }
    if (!insideProgram(path()))
        m_watcher.addPath(path());
    loadFile();
}

void ScriptEditor::loadFile()
{
    QFile file(path());
    if (!file.open(QIODevice::ReadOnly)) {
        m_edit->clear();
        m_edit->setReadOnly(true);
        setStatus(tr("Cannot read %1: %2").arg(QDir::toNativeSeparators(path()), file.errorString()), true);
        return;
    }
    const int line = m_edit->textCursor().blockNumber();
    m_edit->setPlainText(QString::fromUtf8(file.readAll()));
    // Where the cursor was, as near as the new text allows: a reload does not send it home.
    QTextCursor cursor(m_edit->document()->findBlockByNumber(std::min(line, m_edit->document()->blockCount() - 1)));
    m_edit->setTextCursor(cursor);
    const bool readOnly = insideProgram(path());
    m_edit->setReadOnly(readOnly);
    m_edit->document()->setModified(false);
    m_save->setEnabled(false);
    updateMarks();
    if (m_errorLine == 0)
        setStatus(readOnly ? tr("%1 is part of mbscope: shown read-only.").arg(m_list.at(m_current).name)
                           : QDir::toNativeSeparators(path()),
                  false);
}

bool ScriptEditor::save()
{
    if (m_current < 0 || insideProgram(path()))
        return false;
    QFile file(path());
    // Written in place (not replaced): the file stays the one watched, and its permissions stay.
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        setStatus(tr("Not saved: cannot write %1: %2").arg(QDir::toNativeSeparators(path()), file.errorString()), true);
        return false;
    }
    const QByteArray text = m_edit->toPlainText().toUtf8();
    if (file.write(text) != text.size() || !file.flush()) {
        setStatus(tr("Not saved: writing %1 failed: %2").arg(QDir::toNativeSeparators(path()), file.errorString()), true);
        return false;
    }
    file.close();
    m_edit->document()->setModified(false);
    setStatus(tr("Saved %1; the simulator loads it again.").arg(QDir::toNativeSeparators(path())), false);
    return true;
}

void ScriptEditor::onFileChanged(const QString &changed)
{
    // An editor that saves by replacing the file ends the watch: watch the new one.
    if (QFileInfo::exists(changed) && !m_watcher.files().contains(changed))
        m_watcher.addPath(changed);
    if (changed != path())
        return;
    if (m_edit->document()->isModified())
        setStatus(tr("%1 changed on disk; the editor keeps your edits (Save writes them over it).")
                      .arg(QDir::toNativeSeparators(path())),
                  true);
    else
        loadFile();
    Q_EMIT reloadWanted();
}

void ScriptEditor::noteLog(const QString &who, const QString &text, bool error)
{
    if (m_current < 0 || who != m_list.at(m_current).who)
        return;
    if (!error) {
        if (text.startsWith(QLatin1String("loaded")) || text.startsWith(QLatin1String("reloaded"))) {
            markError(0, QString());
            setStatus(tr("%1 loaded.").arg(m_list.at(m_current).name), false);
        }
        return;
    }
    // "s.js:2:15: SyntaxError: ..." (ScriptProblem::toString): the script's name, line, column.
    const QRegularExpression located(QStringLiteral("^%1:(\\d+)(?::\\d+)?:\\s*(.*)$")
                                         .arg(QRegularExpression::escape(m_list.at(m_current).name)),
                                     QRegularExpression::DotMatchesEverythingOption);
    const QRegularExpressionMatch m = located.match(text);
    if (m.hasMatch())
        markError(m.captured(1).toInt(), m.captured(2));
    else
        setStatus(text, true);
}

void ScriptEditor::markError(int line, const QString &message)
{
    m_errorLine = line > 0 && line <= m_edit->document()->blockCount() ? line : 0;
    updateMarks();
    if (m_errorLine > 0) {
        m_edit->setTextCursor(QTextCursor(m_edit->document()->findBlockByNumber(m_errorLine - 1)));
        m_edit->centerCursor();
        setStatus(tr("Line %1: %2").arg(m_errorLine).arg(message), true);
    }
}

// The error's line tinted in the theme's error colour, across the whole width.
void ScriptEditor::updateMarks()
{
    QList<QTextEdit::ExtraSelection> marks;
    if (m_errorLine > 0 && m_errorLine <= m_edit->document()->blockCount()) {
        QTextEdit::ExtraSelection mark;
        mark.cursor = QTextCursor(m_edit->document()->findBlockByNumber(m_errorLine - 1));
        mark.format.setBackground(SeverityStyle::backgroundColor(Severity::Error));
        mark.format.setProperty(QTextFormat::FullWidthSelection, true);
        marks.append(mark);
    }
    m_edit->setExtraSelections(marks);
}

void ScriptEditor::setStatus(const QString &text, bool problem)
{
    m_status->setText(text);
    SeverityStyle::setTextColour(m_status, problem ? Severity::Error : Severity::Ok);
}

QString ScriptEditor::statusText() const
{
    return m_status->text();
}

void ScriptEditor::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    // A theme chosen in Preferences: the colours are read from the new palette.
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::ApplicationPaletteChange) {
        m_highlighter->rehighlight();
        updateMarks();
    }
}

} // namespace mbscope
