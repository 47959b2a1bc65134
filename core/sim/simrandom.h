#pragma once

#include <QtCore/QtGlobal>

namespace mbscope {

// The simulator's random numbers: value generators and fault rules draw from it, so that a seed
// reproduces a run exactly. Its own algorithms throughout (xoshiro256** seeded through
// splitmix64, and hand-written distributions) rather than std:: distributions, whose results
// differ between standard libraries: the same seed gives the same numbers on every platform.
class SimRandom
{
public:
    explicit SimRandom(quint64 seed = 1) { reseed(seed); }
    void reseed(quint64 seed);

    [[nodiscard]] quint64 next();
    // [0, 1) with 53 random bits.
    [[nodiscard]] double uniform();
    // [low, high).
    [[nodiscard]] double uniform(double low, double high) { return low + (high - low) * uniform(); }
    // 0 .. bound-1 (bound > 0), without modulo bias.
    [[nodiscard]] quint64 below(quint64 bound);
    // True with probability p (p <= 0 never, p >= 1 always, drawing a number either way so that
    // the sequence does not depend on p).
    [[nodiscard]] bool chance(double p);
    // Normal (Gauss) by the polar Box-Muller method; the second value of each pair is discarded
    // so that every call consumes whole pairs and draws stay aligned.
    [[nodiscard]] double normal(double mean, double stddev);
    // Exponential with the given mean (inverse transform).
    [[nodiscard]] double exponential(double mean);
    // Log-normal with the given mean and standard deviation of its own (not of its logarithm):
    // exp(N(mu, sigma)) with sigma^2 = ln(1 + (stddev / mean)^2) and mu = ln(mean) - sigma^2 / 2.
    // A product of many independent positive factors tends to it: a wait stretched by several
    // causes at once, right-skewed (most draws below the mean, a few several times the median,
    // far out a longer tail than any exponential's). Consumes one normal pair, whatever the
    // arguments; mean <= 0 gives 0.
    [[nodiscard]] double logNormal(double mean, double stddev);
    // Poisson with mean lambda: multiplication method below 10, PTRS transformed rejection
    // (Hoermann 1993) above.
    [[nodiscard]] quint64 poisson(double lambda);

    // A seed for one consumer (a generator, a rule) from a base seed and up to three labels, so
    // that adding a generator does not change the numbers another one draws.
    [[nodiscard]] static quint64 derive(quint64 seed, quint64 a, quint64 b = 0, quint64 c = 0);

private:
    quint64 m_s[4] = {};
};

} // namespace mbscope
