#pragma once

#include "profile/deviceprofile.h"
#include "script/scriptproblem.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <memory>
#include <vector>

class QTimer;

namespace mbscope {

class ScriptHost;
class SimScriptTables;
class Simulator;
class SimUnit;

// Runs the scripts of a device profile in a simulator: one ScriptHost per unit that names a
// script (and one for the delimited table's), each on the simulator's thread, set on the
// Simulator for its requests, and ticked by a QTimer of its own (PreciseTimer) when its
// settings give tickMs. Nothing is made for a profile without scripts.
//
// Lives in the simulator's thread; the timers and hosts are children, so moveToThread takes
// them along.
class SimScriptDriver : public QObject
{
    Q_OBJECT
public:
    explicit SimScriptDriver(QObject *parent = nullptr);
    ~SimScriptDriver() override;

    // Loads the scripts of profile for the units of sim (matched by id) and sets them on sim.
    // False with every problem in *problems ("unit 2: gamma.js:12:5: SyntaxError: ...") when a
    // script does not load; the others are set.
    // With load false the hosts are made and set but not loaded (they answer as the profile says
    // until load()): for a driver moved to the simulator's thread first, since a QJSEngine
    // belongs to the thread it was made in.
    bool attach(const DeviceProfile &profile, Simulator *sim, QStringList *problems = nullptr, bool load = true);
    // Removes every script from the simulator it was attached to.
    void clear();
    void start();
    void stop();
    // Loads every script again from its file (a fresh engine each): the log says what each did.
    // False when one failed to load: that unit answers as its profile says until the next reload.
    bool reload(QStringList *problems = nullptr) { return loadAll(problems, true); }
    // The first load of hosts attached with load false.
    bool load(QStringList *problems = nullptr) { return loadAll(problems, false); }
    [[nodiscard]] int scriptCount() const { return int(m_scripts.size()); }
    // "unit 1: counter.js", "delimited: line.js".
    [[nodiscard]] QStringList describe() const;

Q_SIGNALS:
    // A script's log line or error; who: "unit 1: counter.js" or "delimited: line.js".
    void logged(const QString &who, const QString &text, bool error);

private:
    struct Script {
        QString who;
        int unitId = -1; // -1: the delimited table's script
        std::unique_ptr<SimScriptTables> tables;
        ScriptHost *host = nullptr;
        QTimer *timer = nullptr;
    };
    void connectLog(const Script &script);
    bool loadAll(QStringList *problems, bool again);

    Simulator *m_sim = nullptr;
    std::vector<Script> m_scripts;
    bool m_running = false;
};

} // namespace mbscope
