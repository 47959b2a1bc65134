#pragma once

#include "scriptanswer.h"
#include "scriptproblem.h"
#include "scriptrequest.h"
#include "scriptsettings.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>

#include <memory>
#include <optional>

class QJSEngine;
class QJSValue;

namespace mbscope {

class ScriptBridge;
class ScriptTables;
class ScriptWatchdog;

// One device script in a QJSEngine of its own: evaluated once (load), then called per request
// (onRequest), per delimited frame (onFrame) and per tick (onTick). docs/profiles.md, "Scripts".
//
// Sandboxed by what the engine is given: a bare QJSEngine (no QQmlEngine, no installExtensions)
// has the ECMAScript built-ins and nothing else: no require, no XMLHttpRequest, no Qt object, no
// files, no network, no processes. The script is given `unit` (its unit's tables), `log(...)`
// and `console.log(...)` (both to logged()). Every call is interrupted once it runs longer than
// the settings' limit (ScriptWatchdog); the host stays usable and the next call runs.
//
// Thread-affine like its engine: create, load and call it on one thread (the simulator's).
class ScriptHost : public QObject
{
    Q_OBJECT
public:
    // tables: the unit's data (not owned; nullptr: a script without data, for checking).
    ScriptHost(const ScriptSettings &settings, ScriptTables *tables, QObject *parent = nullptr);
    ~ScriptHost() override;

    // Reads the file and evaluates it in a new engine (a reload forgets every global of the
    // previous run). False with *problem set: the file cannot be read, a syntax error (line and
    // column), an error thrown by the top-level code (line), or the time limit.
    bool load(ScriptProblem *problem = nullptr);
    [[nodiscard]] bool isLoaded() const { return m_engine != nullptr; }
    // Loads path in a throwaway engine without tables: what the profile loader checks.
    [[nodiscard]] static std::optional<ScriptProblem> check(const ScriptSettings &settings);

    [[nodiscard]] bool handlesRequests() const { return m_handles.request; }
    [[nodiscard]] bool handlesFrames() const { return m_handles.frame; }
    [[nodiscard]] bool handlesTicks() const { return m_handles.tick; }

    // onRequest(request): Normal when the script has none (or is not loaded).
    ScriptAnswer request(const ScriptRequest &request);
    // onFrame(bytes) for a delimited protocol's frame (body without framing): its answer is a
    // string or an array of bytes (kind Adu, the body of the answer), null for silence,
    // undefined for the profile's table.
    ScriptAnswer frame(const QByteArray &body);
    // onTick(time); false when it failed (logged).
    bool tick();

    [[nodiscard]] const ScriptSettings &settings() const { return m_settings; }
    void setSettings(const ScriptSettings &settings) { m_settings = settings; }
    // Milliseconds since the last load(): request.time and onTick's argument.
    [[nodiscard]] double elapsedMs() const;
    [[nodiscard]] quint64 calls() const { return m_calls; }
    [[nodiscard]] quint64 failures() const { return m_failures; }

Q_SIGNALS:
    // A line of log(...) or console.*, or an error (error: true) located with file and line.
    void logged(const QString &text, bool error);

private:
    struct Handles {
        bool request = false;
        bool frame = false;
        bool tick = false;
    };
    // Calls a global function under the watchdog; the result or nullopt with *failure set.
    std::optional<QJSValue> call(const QString &function, const QList<QJSValue> &args, ScriptAnswer *failure);
    [[nodiscard]] ScriptProblem locate(const QJSValue &error, const QStringList &trace) const;
    [[nodiscard]] ScriptAnswer readAnswer(const QJSValue &value, const QString &function) const;
    [[nodiscard]] QJSValue requestObject(const ScriptRequest &request) const;
    void fail(const ScriptAnswer &answer);

    ScriptSettings m_settings;
    ScriptTables *m_tables;
    std::unique_ptr<QJSEngine> m_engine;
    std::unique_ptr<ScriptWatchdog> m_watchdog;
    ScriptBridge *m_bridge = nullptr;
    Handles m_handles;
    QElapsedTimer m_clock;
    quint64 m_calls = 0;
    quint64 m_failures = 0;
};

} // namespace mbscope
