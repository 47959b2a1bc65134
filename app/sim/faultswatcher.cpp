#include "sim/faultswatcher.h"

#include "sim/faultinjector.h"
#include "profile/profileloader.h"

#include <QtCore/QFileInfo>
#include <QtCore/QFileSystemWatcher>
#include <QtCore/QTextStream>

namespace mbscope::app {

FaultsWatcher::FaultsWatcher(const QString &path, FaultInjector *injector, std::optional<quint64> seed, QTextStream &out,
                             QObject *parent)
    : QObject(parent)
    , m_path(QFileInfo(path).absoluteFilePath())
    , m_injector(injector)
    , m_seed(seed)
    , m_out(out)
    , m_watcher(new QFileSystemWatcher(this))
{
    m_settle.setSingleShot(true);
    m_settle.setInterval(150);
    connect(&m_settle, &QTimer::timeout, this, &FaultsWatcher::reload);
    // The directory too: an editor that saves by writing a new file and renaming it over the old
    // one ends the watch on the file itself.
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, [this] { m_settle.start(); });
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, this, [this] {
        if (!m_watcher->files().contains(m_path) && QFileInfo::exists(m_path))
            m_settle.start();
    });
    watch();
}

void FaultsWatcher::watch()
{
    if (!m_watcher->files().contains(m_path) && QFileInfo::exists(m_path))
        m_watcher->addPath(m_path);
    const QString dir = QFileInfo(m_path).absolutePath();
    if (!m_watcher->directories().contains(dir))
        m_watcher->addPath(dir);
}

void FaultsWatcher::reload()
{
    watch();
    if (!QFileInfo::exists(m_path))
        return; // between an editor's remove and rename: the rename comes next
    FaultRulesLoadResult loaded = ProfileLoader::loadFaults(m_path);
    if (!loaded.ok) {
        ++m_refusals;
        m_out << "faults: " << m_path << " was changed but does not read; the rules in force stay:\n"
              << loaded.errorText() << '\n';
        m_out.flush();
        return;
    }
    if (m_seed)
        loaded.rules.seed = *m_seed;
    m_injector->setRules(loaded.rules);
    ++m_reloads;
    const qsizetype n = loaded.rules.rules.size();
    m_out << "faults: reloaded " << m_path << ": " << n << (n == 1 ? " rule" : " rules") << ", seed "
          << loaded.rules.seed << '\n';
    m_out.flush();
}

} // namespace mbscope::app
