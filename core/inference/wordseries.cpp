#include "wordseries.h"

#include "protocol/registervalue.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <span>

namespace mbscope::WordSeries {

QList<double> decode(const BlockSamples &block, int offset, RegisterFormat format)
{
    QList<double> out;
    const int n = format.registerCount();
    out.reserve(block.samples.size());
    for (const QList<quint16> &s : block.samples) {
        if (offset + n > s.size())
            return {};
        const RegisterValueResult r = RegisterValue::fromRegisters(std::span<const quint16>(s.data() + offset, size_t(n)), format);
        out.append(r.value.toDouble());
    }
    return out;
}

bool isConstant(const QList<quint16> &words, std::optional<quint16> value)
{
    if (words.isEmpty())
        return false;
    const quint16 first = words.constFirst();
    if (value && first != *value)
        return false;
    return std::all_of(words.cbegin(), words.cend(), [first](quint16 w) { return w == first; });
}

bool isConstant(const QList<double> &values)
{
    if (values.isEmpty())
        return true;
    const double first = values.constFirst();
    return std::all_of(values.cbegin(), values.cend(), [first](double v) { return v == first || (std::isnan(v) && std::isnan(first)); });
}

double totalVariation(const QList<quint16> &words)
{
    double sum = 0;
    for (qsizetype i = 1; i < words.size(); ++i)
        sum += std::abs(int(words.at(i)) - int(words.at(i - 1)));
    return sum;
}

double totalVariation(const QList<double> &values)
{
    double sum = 0;
    for (qsizetype i = 1; i < values.size(); ++i)
        sum += std::fabs(values.at(i) - values.at(i - 1));
    return sum;
}

int largestJumpBits(const QList<quint16> &words)
{
    int largest = 0;
    for (qsizetype i = 1; i < words.size(); ++i)
        largest = std::max(largest, std::abs(int(words.at(i)) - int(words.at(i - 1))));
    int bits = 0;
    while (largest > 0) {
        ++bits;
        largest >>= 1;
    }
    return bits;
}

double medianStep(const QList<double> &values)
{
    QList<double> steps;
    for (qsizetype i = 1; i < values.size(); ++i) {
        const double d = std::fabs(values.at(i) - values.at(i - 1));
        if (d > 0)
            steps.append(d);
    }
    if (steps.isEmpty())
        return 0;
    std::sort(steps.begin(), steps.end());
    return steps.at(steps.size() / 2);
}

QString smoothness(const QList<double> &values)
{
    if (values.size() < 3)
        return {};
    const auto [low, high] = std::minmax_element(values.cbegin(), values.cend());
    const double range = *high - *low;
    if (range <= 0)
        return {};
    double largest = 0;
    for (qsizetype i = 1; i < values.size(); ++i)
        largest = std::max(largest, std::fabs(values.at(i) - values.at(i - 1)));
    return largest <= range * 0.5 ? QStringLiteral(", smooth") : QStringLiteral(", jumpy");
}

bool smoothExponent(const QList<double> &values)
{
    int steps = 0;
    int jumps = 0;
    for (qsizetype i = 1; i < values.size(); ++i) {
        const double a = std::fabs(values.at(i - 1));
        const double b = std::fabs(values.at(i));
        if (a == 0 || b == 0 || a == b)
            continue;
        ++steps;
        if (std::abs(std::ilogb(a) - std::ilogb(b)) >= 2)
            ++jumps;
    }
    return jumps * 5 <= steps;
}

int significantDigits(double value, bool single)
{
    if (value == 0 || !std::isfinite(value))
        return 1;
    const int most = single ? 9 : 17;
    for (int digits = 1; digits < most; ++digits) {
        const double back = QString::number(value, 'g', digits).toDouble();
        if (single ? float(back) == float(value) : back == value)
            return digits;
    }
    return most;
}

bool countsUp(const QList<quint16> &words)
{
    bool rose = false;
    for (qsizetype i = 1; i < words.size(); ++i) {
        if (words.at(i) < words.at(i - 1))
            return false;
        rose = rose || words.at(i) > words.at(i - 1);
    }
    return rose;
}

QString number(double value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    return QString::number(value, 'g', 7);
}

PairEvidence pairEvidence(const QList<quint16> &hi, const QList<quint16> &lo)
{
    PairEvidence e;
    if (hi.isEmpty() || hi.size() != lo.size())
        return e;
    const bool hiStill = isConstant(hi);
    const bool loStill = isConstant(lo);
    // Sign extension: the high word is 0 or FFFF as the low word's top bit says.
    bool extension = true;
    bool sawNegative = false;
    bool sawPositive = false;
    for (qsizetype i = 0; i < hi.size(); ++i) {
        const bool neg = lo.at(i) >= 0x8000;
        if (hi.at(i) == 0xFFFF && neg)
            sawNegative = true;
        else if (hi.at(i) == 0 && !neg)
            sawPositive = true;
        else
            extension = false;
    }
    // A carry: the high word steps by one when the low word wraps the other way.
    int carries = 0;
    int highChanges = 0;
    int lowChanges = 0;
    bool smallHighSteps = true;
    for (qsizetype i = 1; i < hi.size(); ++i) {
        const int dh = int(hi.at(i)) - int(hi.at(i - 1));
        const int dl = int(lo.at(i)) - int(lo.at(i - 1));
        if (dh != 0)
            ++highChanges;
        if (dl != 0)
            ++lowChanges;
        const int dhWrapped = (dh + 0x10000) % 0x10000;
        if (dh != 0 && !(dhWrapped <= 2 || dhWrapped >= 0xFFFE))
            smallHighSteps = false;
        if ((dhWrapped == 1 && dl < -0x8000) || (dhWrapped == 0xFFFF && dl > 0x8000))
            ++carries;
    }
    if (extension && sawNegative && sawPositive) {
        e.strength = Strength::Strong;
        e.negative = true;
        e.text = QStringLiteral("the high word is 0000 or FFFF as the low word's sign bit says: one signed value around 0");
        return e;
    }
    // A high word of 0x1000 or more is a value beyond 2^28: more likely the top of a float
    // whose mantissa carried (230.99 to 231.01 V) than an integer.
    if (carries > 0 && (hi.constFirst() < 0x1000 || hi.constFirst() >= 0xF000)) {
        e.strength = Strength::Strong;
        e.text = QStringLiteral("the high word steps by 1 exactly when the low word wraps (%1 carries)").arg(carries);
        return e;
    }
    if (hiStill && hi.constFirst() == 0xFFFF && std::all_of(lo.cbegin(), lo.cend(), [](quint16 w) { return w >= 0x8000; })) {
        e.strength = loStill ? Strength::Weak : Strength::Medium;
        e.negative = true;
        e.text = QStringLiteral("high word FFFF over a low word with its sign bit set: a small negative value");
        return e;
    }
    Q_UNUSED(smallHighSteps);
    Q_UNUSED(highChanges);
    Q_UNUSED(lowChanges);
    if (hiStill && hi.constFirst() != 0 && hi.constFirst() <= 0x0FFF && !loStill) {
        e.strength = Strength::Medium;
        e.text = QStringLiteral("the high word stays %1 while the low word moves").arg(hi.constFirst());
        return e;
    }
    if (hiStill && hi.constFirst() == 0 && (!loStill || lo.constFirst() != 0)) {
        e.strength = Strength::Weak;
        e.text = QStringLiteral("the high word stays 0 (could also be a u16 and a register that stays 0)");
        return e;
    }
    return e;
}

} // namespace mbscope::WordSeries
