#pragma once

#include "inference/blocksamples.h"
#include "inference/valueguess.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope::app {

// One sampled block and what inference proposes for it.
struct InferredBlock {
    BlockSamples samples;
    QList<ValueGuess> guesses;
};

// mbscope infer's report: per block a table of values (address, type, kind, scale, unit, last value,
// confidence, evidence) as text, or the same as JSON.
class InferReport
{
public:
    [[nodiscard]] static QString text(const QString &target, quint8 unit, int intervalMs, const QList<InferredBlock> &blocks);
    [[nodiscard]] static QJsonObject json(const QString &target, quint8 unit, int intervalMs, const QList<InferredBlock> &blocks);
    [[nodiscard]] static QString tableName(quint8 function); // "input registers"
};

} // namespace mbscope::app
