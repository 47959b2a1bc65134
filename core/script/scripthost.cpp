#include "scripthost.h"

#include "protocol/hextext.h"
#include "scriptbridge.h"
#include "scriptwatchdog.h"

#include <QtCore/QFile>
#include <QtQml/QJSEngine>
#include <QtQml/QJSValue>

#include <cmath>

namespace mbscope {

namespace {

constexpr qint64 kMaxScriptBytes = 1024 * 1024;
constexpr double kMaxDelayMs = 3600000; // an hour: longer is a mistake, not a device

// Gives the script unit, log and console without the bridge itself (see ScriptBridge).
const QString kPrelude = QStringLiteral(
    "(function (global, host) {\n"
    "  var text = function (args) {\n"
    "    return Array.prototype.map.call(args, function (a) {\n"
    "      return (a !== null && typeof a === 'object') ? JSON.stringify(a) : String(a);\n"
    "    }).join(' ');\n"
    "  };\n"
    "  var log = function () { host.log(text(arguments)); };\n"
    "  Object.defineProperty(global, 'log', { value: log });\n"
    "  Object.defineProperty(global, 'console', { value: Object.freeze({\n"
    "    log: log, info: log, warn: log, error: log, debug: log }) });\n"
    "  Object.defineProperty(global, 'unit', { value: Object.freeze({\n"
    "    id: host.unitId(),\n"
    "    read: function (table, address, count) {\n"
    "      return host.read(String(table), Number(address), count === undefined ? -1 : Number(count)); },\n"
    "    write: function (table, address, values) { return host.write(String(table), Number(address), values); }\n"
    "  }) });\n"
    "})");

QString typeName(const QJSValue &v)
{
    if (v.isNull())
        return QStringLiteral("null");
    if (v.isArray())
        return QStringLiteral("an array");
    if (v.isString())
        return QStringLiteral("a string");
    if (v.isNumber())
        return QStringLiteral("a number");
    if (v.isBool())
        return QStringLiteral("a boolean");
    if (v.isCallable())
        return QStringLiteral("a function");
    return QStringLiteral("an object");
}

bool isInteger(const QJSValue &v, double low, double high)
{
    const double d = v.toNumber();
    return v.isNumber() && std::isfinite(d) && d == std::floor(d) && d >= low && d <= high;
}

// Bytes as an array of numbers 0-255 or hex text ("01 03 00 02").
std::optional<QByteArray> bytesOf(const QJSValue &v, QString *why)
{
    if (v.isString()) {
        const HexTextResult hex = HexText::parse(v.toString());
        if (!hex.ok) {
            *why = hex.error.message;
            return std::nullopt;
        }
        return hex.bytes;
    }
    if (!v.isArray()) {
        *why = QStringLiteral("expected an array of bytes or hex text, found %1").arg(typeName(v));
        return std::nullopt;
    }
    QByteArray out;
    const int length = v.property(QStringLiteral("length")).toInt();
    for (int i = 0; i < length; ++i) {
        const QJSValue b = v.property(quint32(i));
        if (!isInteger(b, 0, 255)) {
            *why = QStringLiteral("[%1] is %2, not a byte (0-255)").arg(i).arg(b.toString());
            return std::nullopt;
        }
        out.append(char(b.toInt()));
    }
    return out;
}

} // namespace

ScriptHost::ScriptHost(const ScriptSettings &settings, ScriptTables *tables, QObject *parent)
    : QObject(parent), m_settings(settings), m_tables(tables)
{
}

ScriptHost::~ScriptHost()
{
    m_watchdog.reset(); // before the engine it interrupts
}

double ScriptHost::elapsedMs() const
{
    return m_clock.isValid() ? double(m_clock.nsecsElapsed()) / 1e6 : 0.0;
}

std::optional<ScriptProblem> ScriptHost::check(const ScriptSettings &settings)
{
    ScriptHost host(settings, nullptr);
    ScriptProblem problem;
    if (host.load(&problem))
        return std::nullopt;
    return problem;
}

bool ScriptHost::load(ScriptProblem *problem)
{
    ScriptProblem local;
    ScriptProblem &p = problem ? *problem : local;
    p = ScriptProblem{m_settings.name, 0, 0, {}};
    m_watchdog.reset();
    delete m_bridge;
    m_bridge = nullptr;
    m_engine.reset();
    m_handles = {};

    QFile file(m_settings.path);
    if (!file.open(QIODevice::ReadOnly)) {
        p.message = file.exists() ? QStringLiteral("cannot be read: %1").arg(file.errorString())
                                  : QStringLiteral("no such script file (looked for %1)").arg(m_settings.path);
        return false;
    }
    if (file.size() > kMaxScriptBytes) {
        p.message = QStringLiteral("%1 bytes is too large for a script (at most %2)").arg(file.size()).arg(kMaxScriptBytes);
        return false;
    }
    const QString source = QString::fromUtf8(file.readAll());

    auto engine = std::make_unique<QJSEngine>();
    auto watchdog = std::make_unique<ScriptWatchdog>(engine.get());
    auto *bridge = new ScriptBridge(engine.get(), m_tables, this);
    QJSEngine::setObjectOwnership(bridge, QJSEngine::CppOwnership);
    connect(bridge, &ScriptBridge::logged, this, [this](const QString &text) { Q_EMIT logged(text, false); });
    const QJSValue install = engine->evaluate(kPrelude, QStringLiteral("prelude"));
    const QJSValue installed = install.call({engine->globalObject(), engine->newQObject(bridge)});
    Q_ASSERT(!installed.isError());

    m_clock.start();
    QStringList trace;
    watchdog->arm(qint64(m_settings.timeoutMs * 1e6));
    const QJSValue result = engine->evaluate(source, m_settings.name, 1, &trace);
    const bool interrupted = watchdog->disarm();
    if (interrupted || result.isError()) {
        p = locate(result, trace);
        if (interrupted)
            p.message = QStringLiteral("the top-level code ran longer than %1 ms: interrupted").arg(m_settings.timeoutMs);
        delete bridge;
        return false;
    }
    const QJSValue global = engine->globalObject();
    m_handles.request = global.property(QStringLiteral("onRequest")).isCallable();
    m_handles.frame = global.property(QStringLiteral("onFrame")).isCallable();
    m_handles.tick = global.property(QStringLiteral("onTick")).isCallable();
    m_engine = std::move(engine);
    m_watchdog = std::move(watchdog);
    m_bridge = bridge;
    return true;
}

ScriptProblem ScriptHost::locate(const QJSValue &error, const QStringList &trace) const
{
    ScriptProblem p;
    p.file = m_settings.name;
    p.message = error.toString();
    p.line = error.property(QStringLiteral("lineNumber")).toInt();
    // An error thrown by unit.read/unit.write is raised in the prelude: the line that matters is
    // the script's frame below it ("read@file:prelude:14\nonRequest@file:t.js:2").
    QString file = error.property(QStringLiteral("fileName")).toString();
    if (file.startsWith(QLatin1String("file:")))
        file = file.mid(5);
    if (file != m_settings.name) {
        const QStringList frames = error.property(QStringLiteral("stack")).toString().split(QLatin1Char('\n'));
        for (const QString &frame : frames) {
            const QString at = frame.section(QLatin1Char('@'), -1);
            if (at.section(QLatin1Char(':'), 0, -2).endsWith(m_settings.name)) {
                p.line = at.section(QLatin1Char(':'), -1).toInt();
                break;
            }
        }
    }
    // evaluate()'s stack trace names "function:line:column:file" per frame; a syntax error's
    // frame carries the column the error object lacks.
    if (!trace.isEmpty()) {
        const QStringList parts = trace.first().split(QLatin1Char(':'));
        if (parts.size() >= 3) {
            const int line = parts.at(1).toInt();
            if (p.line == 0 || p.line == line) {
                p.line = line;
                p.column = parts.at(2).toInt();
            }
        }
    }
    return p;
}

std::optional<QJSValue> ScriptHost::call(const QString &function, const QList<QJSValue> &args, ScriptAnswer *failure)
{
    QJSValue fn = m_engine->globalObject().property(function);
    ++m_calls;
    m_watchdog->arm(qint64(m_settings.timeoutMs * 1e6));
    const QJSValue result = fn.call(args);
    if (m_watchdog->disarm()) {
        ScriptProblem p = locate(result, {});
        p.message = QStringLiteral("%1 ran longer than %2 ms: interrupted").arg(function).arg(m_settings.timeoutMs);
        *failure = ScriptAnswer::failed(p.toString(), true);
        return std::nullopt;
    }
    if (result.isError()) {
        *failure = ScriptAnswer::failed(locate(result, {}).toString());
        return std::nullopt;
    }
    return result;
}

void ScriptHost::fail(const ScriptAnswer &answer)
{
    ++m_failures;
    Q_EMIT logged(answer.note, true);
}

QJSValue ScriptHost::requestObject(const ScriptRequest &r) const
{
    QJSEngine &e = *m_engine;
    QJSValue o = e.newObject();
    const auto optional = [&](const char *key, int value) {
        o.setProperty(QLatin1String(key), value < 0 ? QJSValue(QJSValue::UndefinedValue) : QJSValue(value));
    };
    o.setProperty(QStringLiteral("unit"), r.unit);
    optional("function", r.function);
    optional("address", r.address);
    optional("quantity", r.quantity);
    optional("writeAddress", r.writeAddress);
    QJSValue values = e.newArray(quint32(r.values.size()));
    for (qsizetype i = 0; i < r.values.size(); ++i)
        values.setProperty(quint32(i), int(r.values.at(i)));
    o.setProperty(QStringLiteral("values"), values);
    QJSValue pdu = e.newArray(quint32(r.pdu.size()));
    for (qsizetype i = 0; i < r.pdu.size(); ++i)
        pdu.setProperty(quint32(i), int(quint8(r.pdu.at(i))));
    o.setProperty(QStringLiteral("pdu"), pdu);
    o.setProperty(QStringLiteral("endpoint"), r.endpoint);
    o.setProperty(QStringLiteral("peer"), r.peer);
    optional("transactionId", r.transactionId);
    o.setProperty(QStringLiteral("time"), r.timeMs);
    return o;
}

ScriptAnswer ScriptHost::readAnswer(const QJSValue &v, const QString &function) const
{
    const QString where = m_settings.name + QStringLiteral(": ") + function + QStringLiteral(" returned ");
    ScriptAnswer a;
    if (v.isUndefined())
        return a;
    if (v.isNull()) {
        a.kind = ScriptAnswer::Kind::Silence;
        return a;
    }
    QJSValue values;
    if (v.isArray()) {
        values = v;
    } else if (v.isObject() && !v.isCallable()) {
        static const QStringList keys{QStringLiteral("values"), QStringLiteral("exception"), QStringLiteral("pdu"),
                                      QStringLiteral("adu"), QStringLiteral("delay"), QStringLiteral("silent")};
        QStringList given;
        const QJSValue names = m_engine->globalObject().property(QStringLiteral("Object")).property(QStringLiteral("keys")).call({v});
        const int count = names.property(QStringLiteral("length")).toInt();
        for (int i = 0; i < count; ++i) {
            const QString key = names.property(quint32(i)).toString();
            if (!keys.contains(key))
                return ScriptAnswer::failed(where + QStringLiteral("an object with \"%1\": expected values, exception, pdu, adu, delay or silent").arg(key));
            given.append(key);
        }
        const int answers = int(given.contains(QStringLiteral("values"))) + int(given.contains(QStringLiteral("exception")))
                            + int(given.contains(QStringLiteral("pdu"))) + int(given.contains(QStringLiteral("adu")))
                            + int(given.contains(QStringLiteral("silent")));
        if (answers > 1)
            return ScriptAnswer::failed(where + QStringLiteral("more than one answer (%1): give one of values, exception, pdu, adu or silent")
                                                    .arg(given.join(QStringLiteral(", "))));
        if (given.contains(QStringLiteral("delay"))) {
            const QJSValue delay = v.property(QStringLiteral("delay"));
            const double ms = delay.toNumber();
            if (!delay.isNumber() || !(ms >= 0 && ms <= kMaxDelayMs))
                return ScriptAnswer::failed(where + QStringLiteral("delay %1: expected milliseconds from 0 to %2").arg(delay.toString()).arg(kMaxDelayMs));
            a.delayNs = qint64(std::llround(ms * 1e6));
        }
        if (given.contains(QStringLiteral("silent"))) {
            if (v.property(QStringLiteral("silent")).toBool())
                a.kind = ScriptAnswer::Kind::Silence;
            return a;
        }
        if (given.contains(QStringLiteral("exception"))) {
            const QJSValue code = v.property(QStringLiteral("exception"));
            if (!isInteger(code, 1, 255))
                return ScriptAnswer::failed(where + QStringLiteral("exception %1: expected a code from 1 to 255 (V1.1b3 7: 1 illegal function, 2 illegal data address, 3 illegal data value, 4 server device failure...)").arg(code.toString()));
            a.kind = ScriptAnswer::Kind::Exception;
            a.exceptionCode = code.toInt();
            return a;
        }
        for (const char *key : {"pdu", "adu"}) {
            if (!given.contains(QLatin1String(key)))
                continue;
            QString why;
            const auto bytes = bytesOf(v.property(QLatin1String(key)), &why);
            if (!bytes)
                return ScriptAnswer::failed(where + QLatin1String(key) + QStringLiteral(": ") + why);
            if (bytes->isEmpty())
                return ScriptAnswer::failed(where + QLatin1String(key) + QStringLiteral(": no bytes (for no answer return null)"));
            a.kind = key[0] == 'p' ? ScriptAnswer::Kind::Pdu : ScriptAnswer::Kind::Adu;
            a.bytes = *bytes;
            return a;
        }
        if (!given.contains(QStringLiteral("values")))
            return a; // a delay alone: the profile's answer, later
        values = v.property(QStringLiteral("values"));
        if (!values.isArray())
            return ScriptAnswer::failed(where + QStringLiteral("values as %1: expected an array of numbers").arg(typeName(values)));
    } else {
        return ScriptAnswer::failed(where + typeName(v)
                                    + QStringLiteral(": expected undefined (the profile's answer), null (no answer), an array of values or an object"));
    }
    a.kind = ScriptAnswer::Kind::Values;
    const int length = values.property(QStringLiteral("length")).toInt();
    for (int i = 0; i < length; ++i) {
        const QJSValue x = values.property(quint32(i));
        if (x.isBool()) {
            a.values.append(x.toBool() ? 1 : 0);
            continue;
        }
        if (!isInteger(x, 0, 65535))
            return ScriptAnswer::failed(where + QStringLiteral("values[%1] = %2: expected an integer from 0 to 65535").arg(i).arg(x.toString()));
        a.values.append(quint16(x.toInt()));
    }
    return a;
}

ScriptAnswer ScriptHost::request(const ScriptRequest &request)
{
    if (!m_engine || !m_handles.request)
        return {};
    ScriptAnswer failure;
    const auto result = call(QStringLiteral("onRequest"), {requestObject(request)}, &failure);
    if (!result) {
        fail(failure);
        return failure;
    }
    ScriptAnswer answer = readAnswer(*result, QStringLiteral("onRequest"));
    if (answer.kind == ScriptAnswer::Kind::Failed)
        fail(answer);
    return answer;
}

ScriptAnswer ScriptHost::frame(const QByteArray &body)
{
    if (!m_engine || !m_handles.frame)
        return {};
    ScriptAnswer failure;
    const auto result = call(QStringLiteral("onFrame"), {QJSValue(QString::fromLatin1(body))}, &failure);
    if (!result) {
        fail(failure);
        return failure;
    }
    ScriptAnswer answer;
    if (result->isUndefined())
        return answer;
    if (result->isNull()) {
        answer.kind = ScriptAnswer::Kind::Silence;
        return answer;
    }
    if (result->isString()) {
        const QString text = result->toString();
        for (QChar c : text) {
            if (c.unicode() > 0xFF) {
                answer = ScriptAnswer::failed(m_settings.name + QStringLiteral(": onFrame returned '%1', not a Latin-1 character: a line protocol's answer is bytes").arg(c));
                fail(answer);
                return answer;
            }
        }
        answer.kind = ScriptAnswer::Kind::Adu;
        answer.bytes = text.toLatin1();
        return answer;
    }
    answer = readAnswer(*result, QStringLiteral("onFrame"));
    if (answer.kind == ScriptAnswer::Kind::Values) {
        // An array from onFrame is the answer's bytes.
        QByteArray bytes;
        for (quint16 v : answer.values) {
            if (v > 0xFF) {
                answer = ScriptAnswer::failed(m_settings.name + QStringLiteral(": onFrame returned %1 in its array, not a byte (0-255)").arg(v));
                break;
            }
            bytes.append(char(v));
        }
        if (answer.kind == ScriptAnswer::Kind::Values) {
            answer.kind = ScriptAnswer::Kind::Adu;
            answer.bytes = bytes;
            answer.values.clear();
        }
    }
    if (answer.kind == ScriptAnswer::Kind::Failed)
        fail(answer);
    return answer;
}

bool ScriptHost::tick()
{
    if (!m_engine || !m_handles.tick)
        return true;
    ScriptAnswer failure;
    if (!call(QStringLiteral("onTick"), {QJSValue(elapsedMs())}, &failure)) {
        fail(failure);
        return false;
    }
    return true;
}

} // namespace mbscope

#include "moc_scripthost.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
