#include "watchlogcontrol.h"

#include "watchlogdialog.h"

#include "watch/watchcsvlog.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtGui/QAction>
#include <QtWidgets/QWidget>

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

QString WatchLogControl::directory() const
{
    const QString folder = m_settings.directory.isEmpty() ? QStringLiteral("watch-logs") : m_settings.directory;
    if (QDir::isAbsolutePath(folder))
        return QDir::cleanPath(folder);
    const QString session = m_sessionPath ? m_sessionPath() : QString();
    const QString base = session.isEmpty() ? QDir::currentPath() : QFileInfo(session).absolutePath();
    return QDir::cleanPath(QDir(base).filePath(folder));
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
    const bool restart = m_log != nullptr;
    stop();
    m_settings = edited;
    m_logAction->setChecked(edited.enabled);
    if (restart || (edited.enabled && m_watchesRunning))
        start(m_running);
    return true;
}

void WatchLogControl::setEnabled(bool enabled)
{
    m_settings.enabled = enabled;
    if (!enabled)
        stop();
    else if (m_watchesRunning)
        start(m_running);
}

void WatchLogControl::start(const SessionWatches &watches)
{
    m_running = watches;
    m_watchesRunning = true;
    m_log.reset();
    if (!m_settings.enabled)
        return;
    const QString session = m_sessionPath ? m_sessionPath() : QString();
    const QString base = session.isEmpty() ? QDir::currentPath() : QFileInfo(session).absolutePath();
    auto log = std::make_unique<WatchCsvLog>(m_settings, base);
    QString error;
    if (!log->open(watches.watches, &error)) {
        Q_EMIT message(tr("Not logging to CSV: %1").arg(error));
        return;
    }
    m_log = std::move(log);
    m_failed = false;
    Q_EMIT message(tr("Logging the watches to CSV in %1").arg(QDir::toNativeSeparators(m_log->directory())));
}

void WatchLogControl::stop()
{
    if (!m_log)
        return;
    m_log->close();
    const QString directory = m_log->directory();
    const int files = int(m_log->files().size());
    m_log.reset();
    Q_EMIT message(tr("CSV log closed: %n file(s) in %1", nullptr, files).arg(QDir::toNativeSeparators(directory)));
}

void WatchLogControl::watchesStopped()
{
    m_watchesRunning = false;
    stop();
}

void WatchLogControl::append(const QList<WatchSample> &samples)
{
    if (!m_log)
        return;
    for (const WatchSample &sample : samples) {
        QString error;
        if (!m_log->append(sample.watch, sample.timeMs, watchSampleStatusName(sample.status), sample.values, sample.error, &error)
            && !m_failed) {
            // Said once: a full disk would otherwise say it at every poll.
            m_failed = true;
            Q_EMIT message(tr("The CSV log cannot be written: %1").arg(error));
        }
    }
}

} // namespace mbscope
