#include "scriptbridge.h"

#include "scripttables.h"

#include <QtQml/QJSEngine>

#include <optional>

namespace mbscope {

namespace {

std::optional<ScriptTable> tableNamed(const QString &name)
{
    if (name == QLatin1String("coils"))
        return ScriptTable::Coils;
    if (name == QLatin1String("discrete"))
        return ScriptTable::DiscreteInputs;
    if (name == QLatin1String("input"))
        return ScriptTable::InputRegisters;
    if (name == QLatin1String("holding"))
        return ScriptTable::HoldingRegisters;
    return std::nullopt;
}

const QString kTables = QStringLiteral("expected \"coils\", \"discrete\", \"input\" or \"holding\"");

} // namespace

ScriptBridge::ScriptBridge(QJSEngine *engine, ScriptTables *tables, QObject *parent)
    : QObject(parent), m_engine(engine), m_tables(tables)
{
}

int ScriptBridge::unitId() const
{
    return m_tables ? m_tables->unitId() : 0;
}

QJSValue ScriptBridge::read(const QString &table, int address, int count) const
{
    const auto which = tableNamed(table);
    if (!which) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("unit.read: no table \"%1\": %2").arg(table, kTables));
        return {};
    }
    const int n = count < 0 ? 1 : count;
    if (n > 65536 || address < 0 || address + n > 65536) {
        m_engine->throwError(QJSValue::RangeError, QStringLiteral("unit.read: addresses %1 (+%2) are outside 0-65535").arg(address).arg(n));
        return {};
    }
    QJSValue out = m_engine->newArray(quint32(n));
    for (int i = 0; i < n; ++i) {
        const auto value = m_tables ? m_tables->value(*which, address + i) : std::nullopt;
        if (!value) {
            m_engine->throwError(QJSValue::RangeError,
                                 QStringLiteral("unit.read: address %1 is not in the unit's %2 table").arg(address + i).arg(table));
            return {};
        }
        if (count < 0)
            return QJSValue(int(*value));
        out.setProperty(quint32(i), int(*value));
    }
    return out;
}

bool ScriptBridge::write(const QString &table, int address, const QJSValue &values)
{
    const auto which = tableNamed(table);
    if (!which) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("unit.write: no table \"%1\": %2").arg(table, kTables));
        return false;
    }
    QList<quint16> words;
    const auto take = [&](const QJSValue &v) {
        const double d = v.toNumber();
        if (!v.isNumber() && !v.isBool())
            return false;
        if (!(d >= 0 && d <= 65535))
            return false;
        words.append(quint16(d));
        return true;
    };
    bool ok = true;
    if (values.isArray()) {
        const int length = values.property(QStringLiteral("length")).toInt();
        for (int i = 0; i < length && ok; ++i)
            ok = take(values.property(quint32(i)));
    } else {
        ok = take(values);
    }
    if (!ok) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("unit.write: values are numbers 0-65535 (or true/false for bits)"));
        return false;
    }
    if (address < 0 || address + words.size() > 65536 || !m_tables)
        return false;
    return m_tables->setValues(*which, address, words);
}

void ScriptBridge::log(const QString &text)
{
    Q_EMIT logged(text);
}

} // namespace mbscope

#include "moc_scriptbridge.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
