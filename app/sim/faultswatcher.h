#pragma once

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QTimer>

#include <optional>

class QFileSystemWatcher;
class QTextStream;

namespace mbscope {

class FaultInjector;

namespace app {

// Fault rules "can be changed while running" (issue 4): `mbscope simulate --faults FILE` watches
// the file and, when it is saved again, reads it and hands the new rules to the injector. A file
// that no longer reads is reported with where it is wrong, and the rules in force stay: a typo
// made while a class is polling never turns the faults off silently.
class FaultsWatcher : public QObject
{
    Q_OBJECT
public:
    // seed: --seed, which overrides the file's seed on every reload as it did at start.
    FaultsWatcher(const QString &path, FaultInjector *injector, std::optional<quint64> seed, QTextStream &out,
                  QObject *parent = nullptr);

    // How many times the rules were replaced, and refused, since start.
    [[nodiscard]] int reloads() const { return m_reloads; }
    [[nodiscard]] int refusals() const { return m_refusals; }

private:
    void watch();
    void reload();

    QString m_path;
    FaultInjector *m_injector;
    std::optional<quint64> m_seed;
    QTextStream &m_out;
    QFileSystemWatcher *m_watcher;
    QTimer m_settle; // editors write in several steps (truncate, write, rename): read once they are done
    int m_reloads = 0;
    int m_refusals = 0;
};

} // namespace app
} // namespace mbscope
