#include "watchlogcontrol.h"

#include "watchlogdialog.h"

#include "fleet/watchrunner.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtGui/QAction>
#include <QtWidgets/QWidget>

#include <climits>

namespace mbscope {

WatchLogControl::WatchLogControl(QWidget *parent)
    : QObject(parent)
    , m_parent(parent)
    , m_logAction(new QAction(tr("&Log values to CSV"), this))
    , m_settingsAction(new QAction(tr("CSV log settin&gs\u2026"), this))
{
    m_logAction->setObjectName(QStringLiteral("watchLogAction"));
    m_logAction->setIconText(tr("Log to CSV"));
    m_logAction->setCheckable(true);
    m_logAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    m_logAction->setToolTip(tr("Write the watches' values to CSV files while they run (one file per watch)"));
    connect(m_logAction, &QAction::toggled, this, [this](bool on) {
        if (on == m_settings.enabled)
            return;
        // The first time, where the files go is asked.
        if (on && m_settings.directory.isEmpty() && !editSettings()) {
            m_logAction->setChecked(false);
            return;
        }
        setEnabled(on);
        Q_EMIT settingsChanged();
    });
    connect(m_settingsAction, &QAction::triggered, this, [this] {
        if (editSettings())
            Q_EMIT settingsChanged();
    });
}

WatchLogControl::~WatchLogControl() = default;

void WatchLogControl::setSettings(const WatchLogSettings &settings)
{
    stop();
    m_settings = settings;
    m_logAction->setChecked(settings.enabled);
}

QString WatchLogControl::baseDirectory() const
{
    const QString session = m_sessionPath ? m_sessionPath() : QString();
    return session.isEmpty() ? QDir::currentPath() : QFileInfo(session).absolutePath();
}

QString WatchLogControl::directory() const
{
    const QString folder = m_settings.directory.isEmpty() ? QStringLiteral("watch-logs") : m_settings.directory;
    if (QDir::isAbsolutePath(folder))
        return QDir::cleanPath(folder);
    return QDir::cleanPath(QDir(baseDirectory()).filePath(folder));
}

bool WatchLogControl::editSettings()
{
    WatchLogSettings edited = m_settings;
    if (m_editor) {
        if (!m_editor(edited))
            return false;
    } else {
        WatchLogDialog dialog(m_parent);
        dialog.setSettings(m_settings.directory.isEmpty() ? [&] {
            WatchLogSettings fresh = m_settings;
            fresh.directory = QStringLiteral("watch-logs");
            fresh.enabled = true;
            return fresh;
        }()
                                                          : m_settings);
        if (dialog.exec() != QDialog::Accepted)
            return false;
        edited = dialog.settings();
    }
    m_settings = edited;
    m_logAction->setChecked(edited.enabled);
    apply();
    return true;
}

void WatchLogControl::setEnabled(bool enabled)
{
    m_settings.enabled = enabled;
    apply();
}

void WatchLogControl::apply()
{
    if (!m_runner)
        return;
    if (m_watchesRunning && m_settings.enabled) {
        WatchLogSettings settings = m_settings;
        settings.directory = directory();
        m_runner->setLog(settings);
    } else {
        m_runner->setLog(std::nullopt);
    }
}

void WatchLogControl::start(WatchRunner *runner)
{
    if (m_runner != runner) {
        if (m_runner)
            disconnect(m_runner, nullptr, this, nullptr);
        m_runner = runner;
        m_open = false;
        connect(runner, &WatchRunner::logOpened, this, [this](const QString &directory) {
            m_open = true;
            Q_EMIT message(tr("Logging the watches to CSV in %1").arg(QDir::toNativeSeparators(directory)));
        });
        connect(runner, &WatchRunner::logFailed, this, [this](const QString &error) {
            Q_EMIT message(tr("The CSV log cannot be written: %1").arg(error));
        });
        connect(runner, &WatchRunner::logDropping, this, [this](const QString &) {
            Q_EMIT message(tr("The CSV log cannot keep up with the polls: rows are dropped until it catches up"));
        });
        connect(runner, &WatchRunner::logCaughtUp, this, [this](quint64 rows, const QString &) {
            Q_EMIT message(tr("The CSV log caught up: %n row(s) were dropped", nullptr, int(qMin<quint64>(rows, INT_MAX))));
        });
        connect(runner, &WatchRunner::logClosed, this, [this](const QString &directory, const QStringList &files, quint64 lost) {
            m_open = false;
            QString text = tr("CSV log closed: %n file(s) in %1", nullptr, int(files.size())).arg(QDir::toNativeSeparators(directory));
            if (lost > 0)
                text += QLatin1Char(' ') + tr("(%n row(s) could not be written)", nullptr, int(lost));
            Q_EMIT message(text);
        });
    }
    m_watchesRunning = true;
    apply();
}

void WatchLogControl::stop()
{
    if (m_runner)
        m_runner->setLog(std::nullopt);
}

void WatchLogControl::watchesStopped()
{
    // The runner closes the files once its last samples are written (logClosed says it).
    m_watchesRunning = false;
}

} // namespace mbscope
