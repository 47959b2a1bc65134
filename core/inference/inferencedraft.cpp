#include "inferencedraft.h"

#include "protocol/registervalue.h"

#include "profile/simtable.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QMap>

#include <cmath>
#include <span>

namespace mbscope {

namespace {

QString entryName(const ValueGuess &g)
{
    if (!g.name.isEmpty())
        return g.name;
    const QString what = g.text ? QStringLiteral("text")
                         : !g.quantity.isEmpty() ? g.quantity
                                                 : valueKindName(g.kind);
    return QStringLiteral("%1 at %2").arg(what).arg(g.address);
}

QString description(const ValueGuess &g)
{
    if (g.confirmed)
        return QStringLiteral("confirmed: %1, type %2%3").arg(valueKindName(g.kind), g.typeName(),
                                                               g.scale != 1 ? QStringLiteral(", scale %1").arg(g.scale) : QString());
    QString text = QStringLiteral("guess: %1, type %2 (confidence %3 %): %4")
                       .arg(valueKindName(g.kind), g.typeName())
                       .arg(qRound(g.confidence * 100))
                       .arg(g.evidence);
    if (!g.scaleEvidence.isEmpty())
        text += QStringLiteral("; scale %1 (confidence %2 %): %3").arg(g.scale).arg(qRound(g.scaleConfidence * 100)).arg(g.scaleEvidence);
    return text;
}

} // namespace

QByteArray InferenceDraft::toJson(const QList<ValueGuess> &guesses, quint8 unit, const QString &name,
                                  const QString &source, int intervalMs)
{
    QMap<quint8, QJsonArray> tables;
    for (const ValueGuess &g : guesses) {
        QJsonObject e{{QStringLiteral("address"), int(g.address)},
                      {QStringLiteral("name"), entryName(g)},
                      {QStringLiteral("description"), description(g)}};
        if (g.bit) {
            e.insert(QStringLiteral("value"), g.last != 0);
        } else if (g.text) {
            e.insert(QStringLiteral("type"), QStringLiteral("ascii"));
            e.insert(QStringLiteral("count"), g.registers);
            QJsonArray values;
            for (const quint16 w : g.lastWords)
                values.append(RegisterValue::asciiText(std::span<const quint16>(&w, 1), false));
            e.insert(QStringLiteral("values"), values);
        } else {
            e.insert(QStringLiteral("type"), g.format.name());
            e.insert(QStringLiteral("kind"), valueKindName(g.kind));
            if (!g.unit.isEmpty())
                e.insert(QStringLiteral("unit"), g.unit);
            if (g.scaleRegister >= 0)
                e.insert(QStringLiteral("scaleRegister"), g.scaleRegister); // the scale follows that register, as on the device
            else if (g.scale != 1)
                e.insert(QStringLiteral("scale"), g.scale);
            // The raw words, as text: exact whatever the scale (a NaN or an odd float included).
            const RegisterValueResult raw = RegisterValue::fromRegisters(
                std::span<const quint16>(g.lastWords.constData(), size_t(g.lastWords.size())), g.format);
            if (g.format.isFloat())
                e.insert(QStringLiteral("value"), raw.value.toDouble());
            else
                e.insert(QStringLiteral("value"), raw.value.toText());
            if (g.kind == ValueKind::Measurement && g.maximum > g.minimum && g.typicalStep > 0) {
                e.insert(QStringLiteral("generator"),
                         QJsonObject{{QStringLiteral("kind"), QStringLiteral("randomWalk")},
                                     {QStringLiteral("step"), g.typicalStep},
                                     {QStringLiteral("min"), g.minimum},
                                     {QStringLiteral("max"), g.maximum},
                                     {QStringLiteral("periodMs"), intervalMs}});
            } else if (g.kind == ValueKind::Counter && g.typicalStep > 0) {
                e.insert(QStringLiteral("generator"),
                         QJsonObject{{QStringLiteral("kind"), QStringLiteral("counter")},
                                     {QStringLiteral("step"), g.typicalStep},
                                     {QStringLiteral("periodMs"), intervalMs}});
            }
        }
        tables[g.function].append(e);
    }
    QJsonObject tableObject;
    QJsonArray functions;
    for (auto it = tables.cbegin(); it != tables.cend(); ++it) {
        tableObject.insert(QLatin1String(simTableKey(readTable(it.key()))), it.value());
        functions.append(QStringLiteral("0x%1").arg(int(it.key()), 2, 16, QLatin1Char('0')));
    }
    const QJsonObject unitObject{{QStringLiteral("id"), int(unit)},
                                 {QStringLiteral("name"), QStringLiteral("unit %1").arg(unit)},
                                 {QStringLiteral("functions"), functions},
                                 {QStringLiteral("tables"), tableObject}};
    const QJsonObject profile{
        {QStringLiteral("name"), name},
        {QStringLiteral("description"),
         QStringLiteral("Draft from mbscope infer of %1, unit %2, on %3: every entry's type, order, scale, unit and kind "
                        "are guesses from the values sampled (each description starts 'guess' and says why; 'confirmed' when a person confirmed or corrected it); check them.")
             .arg(source)
             .arg(unit)
             .arg(QDateTime::currentDateTimeUtc().toString(Qt::ISODate))},
        {QStringLiteral("units"), QJsonArray{unitObject}},
    };
    return QJsonDocument(profile).toJson(QJsonDocument::Indented);
}

} // namespace mbscope
