#include "powerrelations.h"

#include "wordseries.h"

#include <algorithm>
#include <cmath>

namespace mbscope {

namespace {

constexpr double kSpread = 0.02;     // the ratio stays within 2 % of its median in most samples
constexpr double kKept = 0.8;        // "most": this share of the samples
constexpr double kDecade = 0.0086;   // the median within 2 % of a power of ten (log10 1.02)

struct Series {
    QList<double> raw;   // the register's numbers over the samples
    QList<double> value; // raw x scale
};

bool voltagePhase(const ValueGuess &g, const QList<double> &values)
{
    return g.quantity == QLatin1String("voltage") && !values.isEmpty()
        && *std::max_element(values.cbegin(), values.cend()) < 300; // line to neutral
}

bool open(const ValueGuess &g)
{
    return !g.text && !g.bit && g.kind == ValueKind::Measurement && g.scaleRegister < 0 && g.quantity.isEmpty()
        && std::fabs(g.scale - 1) < 1e-12;
}

// The median of ratio (skipping samples where it is undefined) when it stays within kSpread of
// it in kKept of the samples and the median is a power of ten: that exponent; else none.
struct Fit {
    bool ok = false;
    int exponent = 0;
    double spread = 1; // the kKept-quantile of |ratio / median - 1|
};

Fit fitPowerOfTen(const QList<double> &ratio, bool floats)
{
    QList<double> r;
    for (const double v : ratio) {
        if (std::isfinite(v) && v > 0)
            r.append(v);
    }
    Fit f;
    if (r.size() < 5 || r.size() * 10 < ratio.size() * 8)
        return f;
    QList<double> sorted = r;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.at(sorted.size() / 2);
    QList<double> dev;
    for (const double v : std::as_const(r))
        dev.append(std::fabs(v / median - 1));
    std::sort(dev.begin(), dev.end());
    f.spread = dev.at(std::min<qsizetype>(dev.size() - 1, qsizetype(std::ceil(kKept * dev.size())) - 1));
    const double l = std::log10(median);
    f.exponent = int(std::lround(l));
    f.ok = f.spread <= kSpread && std::fabs(l - f.exponent) <= kDecade && (!floats || f.exponent == 0);
    return f;
}

// The values moved enough for a relation between them to mean something: the series x is not
// still to within its own rounding.
// How much a series moves against its size: (max - min) / max |value|.
double relativeRange(const QList<double> &raw)
{
    if (raw.isEmpty())
        return 0;
    const auto [lo, hi] = std::minmax_element(raw.cbegin(), raw.cend());
    const double largest = std::max(std::fabs(*lo), std::fabs(*hi));
    return largest > 0 ? (*hi - *lo) / largest : 0;
}

// A relation explains the values only when its ratio stays far steadier than they move: a
// ratio that wanders 1.7 % between values that move 3 % is a coincidence of two slow series.
bool explains(const Fit &fit, const QList<double> &a, const QList<double> &b)
{
    return fit.ok && fit.spread * 5 <= std::min(relativeRange(a), relativeRange(b));
}

bool moves(const QList<double> &raw)
{
    if (raw.isEmpty())
        return false;
    const auto [lo, hi] = std::minmax_element(raw.cbegin(), raw.cend());
    const double largest = std::max(std::fabs(*lo), std::fabs(*hi));
    return largest > 0 && (*hi - *lo) / largest > 0.01;
}

QString percentText(double spread)
{
    return QStringLiteral("%1 %").arg(WordSeries::number(std::round(spread * 1000) / 10));
}

void setScale(ValueGuess &g, double scale, const QString &quantity, const QString &unit, double confidence, const QString &why)
{
    if (!g.format.isFloat())
        g.scale = scale;
    g.quantity = quantity;
    g.unit = unit;
    g.scaleConfidence = confidence;
    g.scaleEvidence = why;
}

} // namespace

void PowerRelations::apply(QList<ValueGuess> &guesses, const BlockSamples &block)
{
    const qsizetype n = guesses.size();
    QList<Series> series(n);
    for (qsizetype i = 0; i < n; ++i) {
        const ValueGuess &g = guesses.at(i);
        if (g.text || g.bit)
            continue;
        series[i].raw = WordSeries::decode(block, g.address - block.address, g.format);
        for (const double v : std::as_const(series[i].raw))
            series[i].value.append(v * g.scale);
    }
    const qsizetype samples = block.samples.size();
    auto usable = [&](qsizetype i) { return series.at(i).raw.size() == samples && samples > 0; };
    QList<qsizetype> voltages;
    QList<qsizetype> factors;
    for (qsizetype i = 0; i < n; ++i) {
        if (!usable(i) || guesses.at(i).kind != ValueKind::Measurement)
            continue;
        if (voltagePhase(guesses.at(i), series.at(i).value))
            voltages.append(i);
        else if (guesses.at(i).quantity == QLatin1String("power factor"))
            factors.append(i);
    }
    if (voltages.isEmpty())
        return;

    auto rescale = [&](qsizetype i) {
        series[i].value.clear();
        for (const double v : std::as_const(series.at(i).raw))
            series[i].value.append(v * guesses.at(i).scale);
    };
    auto name = [&](qsizetype i) { return QString::number(guesses.at(i).address); };

    // 1. S = V x I and P = V x I x PF: y / (V x x [x PF]) at one power of ten.
    struct Power {
        qsizetype power;
        qsizetype current;
        qsizetype voltage;
        qsizetype factor; // -1: apparent power
    };
    QList<Power> powers;
    for (qsizetype y = 0; y < n; ++y) {
        if (!usable(y) || !open(guesses.at(y)) || !moves(series.at(y).raw))
            continue;
        Fit best;
        Power found{-1, -1, -1, -1};
        for (qsizetype x = 0; x < n; ++x) {
            const bool current = guesses.at(x).quantity == QLatin1String("current");
            if (x == y || !usable(x) || !(open(guesses.at(x)) || current) || !moves(series.at(x).raw)
                || guesses.at(x).format.isFloat() != guesses.at(y).format.isFloat())
                continue;
            for (const qsizetype v : std::as_const(voltages)) {
                for (qsizetype f = -1; f < factors.size(); ++f) {
                    QList<double> ratio;
                    for (qsizetype t = 0; t < samples; ++t) {
                        const double pf = f < 0 ? 1.0 : series.at(factors.at(f)).value.at(t);
                        const double denominator = series.at(v).value.at(t) * series.at(x).raw.at(t) * pf;
                        ratio.append(denominator == 0 ? std::nan("") : series.at(y).raw.at(t) / denominator);
                    }
                    const Fit fit = fitPowerOfTen(ratio, guesses.at(y).format.isFloat());
                    if (explains(fit, series.at(x).raw, series.at(y).raw) && (!best.ok || fit.spread < best.spread)) {
                        best = fit;
                        found = {y, x, v, f < 0 ? -1 : factors.at(f)};
                    }
                }
            }
        }
        if (best.ok) {
            powers.append(found);
            // The ratio is scale(x) / scale(y) = 10^exponent. A current already scaled fixes the
            // power's; else the power takes the voltage's scale.
            const ValueGuess &v = guesses.at(found.voltage);
            const bool knownCurrent = !open(guesses.at(found.current));
            double powerScale = v.scale;
            double currentScale = powerScale * std::pow(10.0, best.exponent);
            if (knownCurrent) {
                currentScale = guesses.at(found.current).scale;
                powerScale = currentScale * std::pow(10.0, -best.exponent);
            } else if (currentScale > 1) { // a current in steps of ten amperes: none seen
                currentScale = 1;
                powerScale = std::pow(10.0, -best.exponent);
            }
            const bool apparent = found.factor < 0;
            const QString relation = apparent ? QStringLiteral("%1 = V(%2) x A(%3)").arg(name(y), name(found.voltage), name(found.current))
                                              : QStringLiteral("%1 = V(%2) x A(%3) x PF(%4)")
                                                    .arg(name(y), name(found.voltage), name(found.current), name(found.factor));
            const QString prior = guesses.at(y).format.isFloat() || knownCurrent
                ? QString()
                : QStringLiteral("; physics fixes the ratio of the two scales, not the pair: the power is taken at the voltage's x %1")
                      .arg(WordSeries::number(v.scale));
            const double confidence = guesses.at(y).format.isFloat() ? 0.85 : 0.6;
            if (open(guesses.at(found.current)))
                setScale(guesses[found.current], currentScale, QStringLiteral("current"), QStringLiteral("A"), confidence,
                         QStringLiteral("%1 over %2 samples (within %3) with the power at x %4: x %5 here%6")
                             .arg(relation)
                             .arg(samples)
                             .arg(percentText(best.spread), WordSeries::number(powerScale), WordSeries::number(currentScale), prior));
            setScale(guesses[y], powerScale, apparent ? QStringLiteral("apparent power") : QStringLiteral("power"),
                     apparent ? QStringLiteral("VA") : QStringLiteral("W"), confidence,
                     QStringLiteral("%1 over %2 samples (within %3) with the current at x %4%5")
                         .arg(relation)
                         .arg(samples)
                         .arg(percentText(best.spread), WordSeries::number(currentScale), prior));
            rescale(found.current);
            rescale(y);
        }
    }

    // 2. Reactive power of a phase: |Q| = sqrt(S^2 - P^2).
    for (const Power &s : std::as_const(powers)) {
        if (s.factor >= 0)
            continue;
        for (const Power &p : std::as_const(powers)) {
            if (p.factor < 0 || p.current != s.current)
                continue;
            for (qsizetype z = 0; z < n; ++z) {
                if (!usable(z) || !open(guesses.at(z)) || !moves(series.at(z).raw)
                    || guesses.at(z).format.isFloat() != guesses.at(s.power).format.isFloat())
                    continue;
                QList<double> ratio;
                for (qsizetype t = 0; t < samples; ++t) {
                    const double a = series.at(s.power).value.at(t);
                    const double b = series.at(p.power).value.at(t);
                    const double q = std::sqrt(std::max(0.0, a * a - b * b));
                    ratio.append(q == 0 ? std::nan("") : std::fabs(series.at(z).raw.at(t)) / q);
                }
                const Fit fit = fitPowerOfTen(ratio, guesses.at(z).format.isFloat());
                if (!explains(fit, series.at(z).raw, series.at(z).raw))
                    continue;
                setScale(guesses[z], std::pow(10.0, -fit.exponent), QStringLiteral("reactive power"), QStringLiteral("var"), 0.6,
                         QStringLiteral("|%1| = sqrt(VA(%2)^2 - W(%3)^2) over %4 samples (within %5)")
                             .arg(name(z), name(s.power), name(p.power)).arg(samples).arg(percentText(fit.spread)));
                rescale(z);
                break;
            }
        }
    }

    // 3. Totals: the sum of three values of one quantity.
    QList<qsizetype> known;
    for (qsizetype i = 0; i < n; ++i) {
        const QString &q = guesses.at(i).quantity;
        if (usable(i) && guesses.at(i).kind == ValueKind::Measurement
            && (q == QLatin1String("current") || q == QLatin1String("power") || q == QLatin1String("apparent power")
                || q == QLatin1String("reactive power")))
            known.append(i);
    }
    for (qsizetype z = 0; z < n; ++z) {
        if (!usable(z) || !open(guesses.at(z)) || !moves(series.at(z).raw))
            continue;
        bool done = false;
        for (qsizetype a = 0; a < known.size() && !done; ++a) {
            for (qsizetype b = a + 1; b < known.size() && !done; ++b) {
                for (qsizetype c = b + 1; c < known.size() && !done; ++c) {
                    const qsizetype i = known.at(a), j = known.at(b), k = known.at(c);
                    const QString &q = guesses.at(i).quantity;
                    if (guesses.at(j).quantity != q || guesses.at(k).quantity != q
                        || guesses.at(z).format.isFloat() != guesses.at(i).format.isFloat())
                        continue;
                    QList<double> ratio;
                    for (qsizetype t = 0; t < samples; ++t) {
                        const double sum = series.at(i).value.at(t) + series.at(j).value.at(t) + series.at(k).value.at(t);
                        ratio.append(series.at(z).raw.at(t) == 0 ? std::nan("") : sum / series.at(z).raw.at(t));
                    }
                    const Fit fit = fitPowerOfTen(ratio, guesses.at(z).format.isFloat());
                    if (!fit.ok)
                        continue;
                    setScale(guesses[z], std::pow(10.0, fit.exponent), q, guesses.at(i).unit, 0.6,
                             QStringLiteral("%1 = %2 + %3 + %4 (%5) over %6 samples (within %7)")
                                 .arg(name(z), name(i), name(j), name(k), q).arg(samples).arg(percentText(fit.spread)));
                    rescale(z);
                    done = true;
                }
            }
        }
    }
}

} // namespace mbscope
