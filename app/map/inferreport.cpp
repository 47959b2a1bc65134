#include "map/inferreport.h"

#include <QtCore/QJsonArray>

namespace mbscope::app {

QString InferReport::tableName(quint8 function)
{
    switch (function) {
    case 1: return QStringLiteral("coils");
    case 2: return QStringLiteral("discrete inputs");
    case 4: return QStringLiteral("input registers");
    default: return QStringLiteral("holding registers");
    }
}

QString InferReport::text(const QString &target, quint8 unit, int intervalMs, const QList<InferredBlock> &blocks)
{
    QString out = QStringLiteral("infer %1 unit %2: %3 block%4, sampled every %5 ms\n")
                      .arg(target)
                      .arg(unit)
                      .arg(blocks.size())
                      .arg(blocks.size() == 1 ? QString() : QStringLiteral("s"))
                      .arg(intervalMs);
    for (const InferredBlock &b : blocks) {
        const BlockSamples &s = b.samples;
        out += QStringLiteral("\n%1 (%2) %3-%4: %5 samples%6\n")
                   .arg(tableName(s.function))
                   .arg(int(s.function), 2, 10, QLatin1Char('0'))
                   .arg(s.address)
                   .arg(int(s.address) + s.count() - 1)
                   .arg(s.samples.size())
                   .arg(s.failedReads ? QStringLiteral(", %1 reads failed").arg(s.failedReads) : QString());
        if (s.samples.isEmpty()) {
            out += QStringLiteral("  nothing read: no guesses\n");
            continue;
        }
        out += QStringLiteral("  %1 %2 %3 %4 %5 %6 %7 %8\n")
                   .arg(QStringLiteral("address"), -8)
                   .arg(QStringLiteral("type"), -10)
                   .arg(QStringLiteral("kind"), -12)
                   .arg(QStringLiteral("scale"), -6)
                   .arg(QStringLiteral("unit"), -5)
                   .arg(QStringLiteral("last"), -14)
                   .arg(QStringLiteral("conf"), -5)
                   .arg(QStringLiteral("evidence"));
        for (const ValueGuess &g : b.guesses) {
            QString evidence = g.evidence;
            if (!g.scaleEvidence.isEmpty())
                evidence += QStringLiteral("; scale (%1 %): ").arg(qRound(g.scaleConfidence * 100)) + g.scaleEvidence;
            QString last = g.text ? QLatin1Char('"') + g.lastText + QLatin1Char('"') : g.lastText;
            if (last.size() > 14)
                last = last.left(13) + QChar(0x2026);
            out += QStringLiteral("  %1 %2 %3 %4 %5 %6 %7 %8\n")
                       .arg(QString::number(g.address), -8)
                       .arg(g.typeName(), -10)
                       .arg(valueKindName(g.kind), -12)
                       .arg(QString::number(g.scale), -6)
                       .arg(g.unit.isEmpty() ? QStringLiteral("-") : g.unit, -5)
                       .arg(last, -14)
                       .arg(QStringLiteral("%1%").arg(qRound(g.confidence * 100)), -5)
                       .arg(evidence);
        }
    }
    return out;
}

QJsonObject InferReport::json(const QString &target, quint8 unit, int intervalMs, const QList<InferredBlock> &blocks)
{
    QJsonArray blockArray;
    for (const InferredBlock &b : blocks) {
        QJsonArray values;
        for (const ValueGuess &g : b.guesses) {
            QJsonObject v{{QStringLiteral("address"), int(g.address)},
                          {QStringLiteral("registers"), g.registers},
                          {QStringLiteral("type"), g.bit ? QStringLiteral("bit") : g.text ? QStringLiteral("ascii") : g.format.name()},
                          {QStringLiteral("kind"), valueKindName(g.kind)},
                          {QStringLiteral("scale"), g.scale},
                          {QStringLiteral("unit"), g.unit},
                          {QStringLiteral("quantity"), g.quantity},
                          {QStringLiteral("confidence"), g.confidence},
                          {QStringLiteral("evidence"), g.evidence},
                          {QStringLiteral("scaleEvidence"), g.scaleEvidence},
                          {QStringLiteral("scaleConfidence"), g.scaleConfidence},
                          {QStringLiteral("minimum"), g.minimum},
                          {QStringLiteral("maximum"), g.maximum},
                          {QStringLiteral("last"), g.text ? QJsonValue(g.lastText) : QJsonValue(g.last)}};
            if (g.scaleRegister >= 0)
                v.insert(QStringLiteral("scaleRegister"), g.scaleRegister);
            values.append(v);
        }
        blockArray.append(QJsonObject{{QStringLiteral("function"), int(b.samples.function)},
                                      {QStringLiteral("address"), int(b.samples.address)},
                                      {QStringLiteral("count"), b.samples.count()},
                                      {QStringLiteral("samples"), int(b.samples.samples.size())},
                                      {QStringLiteral("failedReads"), b.samples.failedReads},
                                      {QStringLiteral("values"), values}});
    }
    return QJsonObject{{QStringLiteral("target"), target},
                       {QStringLiteral("unit"), int(unit)},
                       {QStringLiteral("intervalMs"), intervalMs},
                       {QStringLiteral("blocks"), blockArray}};
}

} // namespace mbscope::app
