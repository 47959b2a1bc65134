#include "readingalternatives.h"

#include "wordseries.h"

#include "protocol/registervalue.h"

#include <cmath>
#include <span>

namespace mbscope {

QString Reading::label() const
{
    if (std::fabs(scale - 1) < 1e-12)
        return format.name();
    return QStringLiteral("%1 x%2").arg(format.name(), WordSeries::number(scale));
}

QString Reading::valueText(const QList<quint16> &words) const
{
    const int n = format.registerCount();
    if (words.size() < n)
        return {};
    const RegisterValueResult r = RegisterValue::fromRegisters(std::span<const quint16>(words.constData(), size_t(n)), format);
    const double v = r.value.toDouble();
    if (format.isFloat() && !std::isfinite(v))
        return std::isnan(v) ? QStringLiteral("NaN") : v > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    if (format.isFloat() && std::fabs(v) >= 1e15)
        return QString::number(v, 'g', 4); // not a measurement: said short
    return WordSeries::number(v * scale);
}

QList<Reading> ReadingAlternatives::of(const ValueGuess &guess)
{
    QList<Reading> out{Reading{guess.format, guess.scale}};
    if (guess.text || guess.bit)
        return out;
    auto add = [&out](RegisterType type, RegisterOrder order, double scale) {
        const Reading r{RegisterFormat(type, order), scale};
        if (!out.contains(r) && out.size() < kMost)
            out.append(r);
    };
    const double scale = guess.format.isFloat() ? 1 : guess.scale;
    switch (guess.registers) {
    case 1:
        add(RegisterType::UInt16, RegisterOrder::ABCD, 1);
        add(RegisterType::Int16, RegisterOrder::ABCD, 1);
        for (const double s : {0.1, 0.01, 0.001})
            add(guess.format.isSigned() ? RegisterType::Int16 : RegisterType::UInt16, RegisterOrder::ABCD, s);
        add(guess.format.isSigned() ? RegisterType::UInt16 : RegisterType::Int16, RegisterOrder::ABCD, 0.1);
        break;
    case 2:
        for (const RegisterOrder o : {RegisterOrder::ABCD, RegisterOrder::CDAB}) {
            add(RegisterType::Float32, o, 1);
            add(RegisterType::UInt32, o, scale);
            add(RegisterType::Int32, o, scale);
        }
        break;
    case 4:
        for (const RegisterOrder o : {RegisterOrder::ABCD, RegisterOrder::DCBA}) {
            add(RegisterType::Float64, o, 1);
            add(RegisterType::UInt64, o, scale);
        }
        break;
    default:
        break;
    }
    return out;
}

} // namespace mbscope
