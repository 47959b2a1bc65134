#include "simscriptpanel.h"

#include "scripteditor.h"

#include "sim/simulatorhost.h"

#include <QtCore/QDateTime>
#include <QtGui/QFontDatabase>
#include <QtGui/QFontMetrics>
#include <QtGui/QTextCursor>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

SimScriptPanel::SimScriptPanel(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 4, 0, 0);
    auto *row = new QHBoxLayout;
    m_scripts = new QLabel(this);
    m_scripts->setObjectName(QStringLiteral("simScripts"));
    m_scripts->setWordWrap(true);
    row->addWidget(m_scripts, 1);
    m_reload = new QPushButton(tr("Re&load scripts"), this);
    m_reload->setObjectName(QStringLiteral("simReloadScripts"));
    m_reload->setToolTip(tr("Loads every script of this simulator again from its file, with fresh globals."));
    row->addWidget(m_reload);
    m_clear = new QPushButton(tr("Clear lo&g"), this);
    m_clear->setObjectName(QStringLiteral("simClearScriptLog"));
    row->addWidget(m_clear);
    layout->addLayout(row);
    // The script on the left, what it logs on the right.
    m_split = new QSplitter(Qt::Horizontal, this);
    m_split->setObjectName(QStringLiteral("simScriptSplit"));
    m_split->setChildrenCollapsible(false);
    m_editor = new ScriptEditor(m_split);
    m_log = new QPlainTextEdit(m_split);
    m_log->setObjectName(QStringLiteral("simScriptLog"));
    m_log->setReadOnly(true);
    m_log->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_log->setMaximumBlockCount(kLogLines);
    m_log->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // Room for several errors at once, however small the dock.
    m_log->setMinimumHeight(8 * QFontMetrics(m_log->font()).lineSpacing());
    m_log->setPlaceholderText(tr("What the scripts write with log(...) or console.log(...), and their errors with file and line."));
    m_split->addWidget(m_editor);
    m_split->addWidget(m_log);
    m_split->setStretchFactor(0, 3);
    m_split->setStretchFactor(1, 2);
    layout->addWidget(m_split, 1);

    connect(m_reload, &QPushButton::clicked, this, &SimScriptPanel::reload);
    connect(m_editor, &ScriptEditor::reloadWanted, this, &SimScriptPanel::reload);
    connect(m_clear, &QPushButton::clicked, this, [this] {
        if (m_host)
            m_logs.remove(m_host);
        m_log->clear();
    });
    setHost(nullptr);
}

void SimScriptPanel::watch(SimulatorHost *host)
{
    connect(host, &SimulatorHost::scriptLogged, this, [this, host](const QString &who, const QString &text, bool error) {
        const QString time = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss.zzz"));
        append(host, error ? tr("%1  %2  error: %3").arg(time, who, text) : QStringLiteral("%1  %2  %3").arg(time, who, text));
        if (host == m_host)
            m_editor->noteLog(who, text, error);
    });
}

void SimScriptPanel::forget(SimulatorHost *host)
{
    m_logs.remove(host);
    if (host == m_host)
        setHost(nullptr);
}

void SimScriptPanel::append(SimulatorHost *host, const QString &line)
{
    QStringList &lines = m_logs[host];
    lines.append(line);
    if (lines.size() > kLogLines)
        lines.remove(0, lines.size() - kLogLines);
    if (host == m_host)
        m_log->appendPlainText(line);
}

void SimScriptPanel::setHost(SimulatorHost *host)
{
    m_host = host;
    m_editor->setHost(host);
    m_log->clear();
    const QStringList scripts = host ? host->scripts() : QStringList();
    m_reload->setEnabled(!scripts.isEmpty());
    m_clear->setEnabled(host != nullptr);
    if (!host)
        m_scripts->setText(tr("No simulator selected."));
    else if (scripts.isEmpty())
        m_scripts->setText(tr("This simulator's profile names no script (docs/profiles.md, \"Scripts\")."));
    else
        m_scripts->setText(tr("Scripts: %1").arg(scripts.join(QStringLiteral(", "))));
    if (host) {
        m_log->setPlainText(m_logs.value(host).join(QLatin1Char('\n')));
        m_log->moveCursor(QTextCursor::End); // the newest lines in view
    }
}

void SimScriptPanel::reload()
{
    if (m_host)
        m_host->reloadScripts();
}

QString SimScriptPanel::logText() const
{
    return m_log->toPlainText();
}

} // namespace mbscope
