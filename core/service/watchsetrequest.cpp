#include "watchsetrequest.h"

#include "protocol/registervalue.h"
#include "watch/watchdecoder.h"
#include "watch/watchblock.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QStringList>

#include <cmath>

namespace mbscope {

namespace {

const WatchPoint *findPoint(const WatchDefinition &watch, const QString &key)
{
    for (const WatchPoint &p : watch.points) {
        if (!p.name.isEmpty() && p.name == key)
            return &p;
    }
    bool ok = false;
    const uint address = key.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? key.mid(2).toUInt(&ok, 16) : key.toUInt(&ok);
    if (!ok)
        return nullptr;
    for (const WatchPoint &p : watch.points) {
        if (p.address == address)
            return &p;
    }
    return nullptr;
}

QString writableList(const WatchDefinition &watch)
{
    QStringList names;
    for (const WatchPoint &p : watch.points) {
        if (p.writable)
            names.append(p.name.isEmpty() ? QString::number(p.address) : p.name);
    }
    return names.isEmpty() ? QStringLiteral("none is") : names.join(QStringLiteral(", ")) + (names.size() == 1 ? QStringLiteral(" is") : QStringLiteral(" are"));
}

QString describe(const QJsonValue &v)
{
    if (v.isString())
        return QStringLiteral("the text \"%1\"").arg(v.toString());
    if (v.isDouble())
        return QStringLiteral("the number %1").arg(v.toDouble());
    if (v.isBool())
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.isNull())
        return QStringLiteral("null");
    return v.isArray() ? QStringLiteral("an array") : QStringLiteral("an object");
}

} // namespace

WatchSetRequest WatchSetRequest::parse(const WatchDefinition &watch, const QByteArray &payload)
{
    WatchSetRequest request;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(payload, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        request.error = QStringLiteral("not JSON at byte %1: %2 (expected an object such as {\"setpoint\": 21.5})")
                            .arg(parseError.offset)
                            .arg(parseError.errorString());
        return request;
    }
    if (!doc.isObject() || doc.object().isEmpty()) {
        request.error = QStringLiteral("expected a JSON object of points and values, such as {\"setpoint\": 21.5}");
        return request;
    }
    const bool coils = watch.function == 1;
    if (!coils && watch.function != 3 && watch.function != 0x18) {
        request.error = QStringLiteral("watch '%1' reads %2, which cannot be written").arg(watch.name,
            watch.function == 2 ? QStringLiteral("discrete inputs") : QStringLiteral("input registers"));
        return request;
    }
    const QJsonObject o = doc.object();
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString key = it.key();
        const QJsonValue value = it.value();
        const auto fail = [&](const QString &why) {
            request.writes.clear();
            request.error = QStringLiteral("'%1': %2").arg(key, why);
            return request;
        };
        const WatchPoint *point = findPoint(watch, key);
        if (!point)
            return fail(QStringLiteral("no such point in watch '%1' (writable: %2)").arg(watch.name, writableList(watch)));
        if (!point->writable)
            return fail(QStringLiteral("not marked writable in watch '%1' (writable: %2)").arg(watch.name, writableList(watch)));
        Write write{key, point->address, {}};
        if (coils) {
            if (value.isBool())
                write.words = {quint16(value.toBool() ? 1 : 0)};
            else if (value.isDouble() && (value.toDouble() == 0 || value.toDouble() == 1))
                write.words = {quint16(value.toDouble())};
            else
                return fail(QStringLiteral("a coil takes true, false, 1 or 0, not %1").arg(describe(value)));
            request.writes.append(write);
            continue;
        }
        const RegisterFormat format = WatchBlock::effectiveFormat(watch, *point);
        RegisterValueResult encoded;
        if (value.isString()) {
            encoded = RegisterValue::fromText(value.toString(), format);
        } else if (value.isDouble()) {
            if (point->scale == 0)
                return fail(QStringLiteral("the point's scale is 0, so no raw value gives %1").arg(value.toDouble()));
            double raw = (value.toDouble() - point->offset) / point->scale;
            if (!format.isFloat())
                raw = std::round(raw);
            encoded = RegisterValue::fromDouble(raw, format);
        } else {
            return fail(QStringLiteral("expected a number or a text in the format %1, not %2").arg(format.name(), describe(value)));
        }
        if (!encoded.ok)
            return fail(encoded.error);
        write.words = encoded.value.registers();
        request.writes.append(write);
    }
    return request;
}

} // namespace mbscope
