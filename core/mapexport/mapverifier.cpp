#include "mapverifier.h"

#include <cmath>

namespace mbscope {

namespace {

QString numberText(double v)
{
    if (std::isnan(v))
        return QStringLiteral("NaN");
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("Inf") : QStringLiteral("-Inf");
    return QString::number(v, 'g', 10);
}

} // namespace

QList<MapVerdict> MapVerifier::judge(const QList<MapPoint> &points, const QList<ExportBlock> &blocks,
                                     const QList<ExportBlockReading> &readings)
{
    QList<MapVerdict> verdicts;
    for (qsizetype b = 0; b < blocks.size(); ++b) {
        const ExportBlock &block = blocks.at(b);
        const ExportBlockReading reading = b < readings.size() ? readings.at(b) : ExportBlockReading{{}, QStringLiteral("not read")};
        for (qsizetype index : block.points) {
            const MapPoint &p = points.at(index);
            MapVerdict v;
            v.point = index;
            const int offset = p.address - block.start;
            if (!reading.error.isEmpty() || offset + p.registers > reading.words.size()) {
                v.problem = reading.error.isEmpty() ? QStringLiteral("the answer is too short") : reading.error;
                verdicts.append(v);
                continue;
            }
            const std::span<const quint16> words(reading.words.constData() + offset, size_t(p.registers));
            if (p.isString()) {
                v.value = QLatin1Char('"') + p.decodeText(words) + QLatin1Char('"');
                verdicts.append(v);
                continue;
            }
            if (p.isNotImplemented(words)) {
                v.value = QStringLiteral("not implemented");
                verdicts.append(v);
                continue;
            }
            const double value = p.decode(words).value_or(std::nan(""));
            v.value = numberText(value);
            if (!std::isfinite(value))
                v.problem = QStringLiteral("%1 is not finite").arg(v.value);
            else if (p.min && value < *p.min)
                v.problem = QStringLiteral("%1 is below min %2").arg(v.value, numberText(*p.min));
            else if (p.max && value > *p.max)
                v.problem = QStringLiteral("%1 is above max %2").arg(v.value, numberText(*p.max));
            verdicts.append(v);
        }
    }
    return verdicts;
}

} // namespace mbscope
