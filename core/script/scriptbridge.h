#pragma once

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtQml/QJSValue>

class QJSEngine;

namespace mbscope {

class ScriptTables;

// What a script reaches of the simulator, and nothing more: its unit's tables and the log.
// Never handed to the script itself: the prelude of ScriptHost wraps it in a frozen plain
// object (`unit.read`, `unit.write`, `unit.id`) and in log() and console.*, so that no QObject
// method (deleteLater, signals) is within reach.
class ScriptBridge : public QObject
{
    Q_OBJECT
public:
    ScriptBridge(QJSEngine *engine, ScriptTables *tables, QObject *parent = nullptr);

    Q_INVOKABLE int unitId() const;
    // A value (count < 0) or an array of count values; throws a TypeError or RangeError into the
    // script for a table name it does not know or an address the unit does not have.
    Q_INVOKABLE QJSValue read(const QString &table, int address, int count) const;
    // A number or an array of numbers from address on; false when an address is not in the unit.
    Q_INVOKABLE bool write(const QString &table, int address, const QJSValue &values);
    Q_INVOKABLE void log(const QString &text);

Q_SIGNALS:
    void logged(const QString &text);

private:
    QJSEngine *m_engine;
    ScriptTables *m_tables;
};

} // namespace mbscope
