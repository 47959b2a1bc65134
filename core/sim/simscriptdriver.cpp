#include "sim/simscriptdriver.h"

#include "script/scripthost.h"
#include "sim/simscripttables.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtCore/QTimer>

#include <cmath>

namespace mbscope {

SimScriptDriver::SimScriptDriver(QObject *parent)
    : QObject(parent)
{
}

SimScriptDriver::~SimScriptDriver()
{
    clear();
}

void SimScriptDriver::connectLog(const Script &script)
{
    const QString who = script.who;
    connect(script.host, &ScriptHost::logged, this,
            [this, who](const QString &text, bool error) { Q_EMIT logged(who, text, error); });
}

bool SimScriptDriver::attach(const DeviceProfile &profile, Simulator *sim, QStringList *problems, bool load)
{
    clear();
    m_sim = sim;
    bool ok = true;
    const auto add = [&](const ScriptSettings &settings, SimUnit *unit, int unitId, const QString &who) {
        Script script;
        script.who = who;
        script.unitId = unitId;
        script.tables = std::make_unique<SimScriptTables>(unit);
        script.host = new ScriptHost(settings, script.tables.get(), this);
        connectLog(script);
        ScriptProblem problem;
        if (load && !script.host->load(&problem)) {
            ok = false;
            if (problems)
                problems->append(who.section(QLatin1Char(':'), 0, 0) + QStringLiteral(": ") + problem.toString());
            Q_EMIT logged(who, problem.toString(), true);
        }
        if (settings.tickMs > 0) {
            script.timer = new QTimer(this);
            script.timer->setTimerType(Qt::PreciseTimer);
            script.timer->setInterval(std::max(1, int(std::lround(settings.tickMs))));
            ScriptHost *host = script.host;
            connect(script.timer, &QTimer::timeout, host, [host] { host->tick(); });
        }
        if (unitId >= 0)
            sim->setScript(quint8(unitId), script.host);
        else
            sim->setLineScript(script.host);
        m_scripts.push_back(std::move(script));
    };
    for (const UnitProfile &unit : profile.units) {
        if (unit.script.isEmpty())
            continue;
        SimUnit *simUnit = sim->unit(unit.id);
        if (!simUnit)
            continue;
        add(unit.script, simUnit, unit.id, QStringLiteral("unit %1: %2").arg(unit.id).arg(unit.script.name));
    }
    if (!profile.delimited.script.isEmpty()) {
        const QList<quint8> ids = sim->unitIds();
        add(profile.delimited.script, ids.isEmpty() ? nullptr : sim->unit(ids.first()), -1,
            QStringLiteral("delimited: %1").arg(profile.delimited.script.name));
    }
    return ok;
}

void SimScriptDriver::clear()
{
    stop();
    for (Script &script : m_scripts) {
        if (m_sim && script.unitId >= 0 && m_sim->script(quint8(script.unitId)) == script.host)
            m_sim->setScript(quint8(script.unitId), nullptr);
        else if (m_sim && script.unitId < 0 && m_sim->lineScript() == script.host)
            m_sim->setLineScript(nullptr);
        delete script.timer;
        delete script.host;
    }
    m_scripts.clear();
}

void SimScriptDriver::start()
{
    m_running = true;
    for (Script &script : m_scripts) {
        if (script.timer)
            script.timer->start();
    }
}

void SimScriptDriver::stop()
{
    m_running = false;
    for (Script &script : m_scripts) {
        if (script.timer)
            script.timer->stop();
    }
}

bool SimScriptDriver::loadAll(QStringList *problems, bool again)
{
    bool ok = true;
    for (Script &script : m_scripts) {
        ScriptProblem problem;
        if (script.host->load(&problem)) {
            Q_EMIT logged(script.who, again ? QStringLiteral("reloaded") : QStringLiteral("loaded"), false);
            continue;
        }
        ok = false;
        if (problems)
            problems->append(script.who.section(QLatin1Char(':'), 0, 0) + QStringLiteral(": ") + problem.toString());
        Q_EMIT logged(script.who, problem.toString() + QStringLiteral(" (the profile answers until the next reload)"), true);
    }
    return ok;
}

QStringList SimScriptDriver::describe() const
{
    QStringList out;
    for (const Script &script : m_scripts)
        out.append(script.who);
    return out;
}

} // namespace mbscope

#include "moc_simscriptdriver.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
