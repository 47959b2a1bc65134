#include "sim/simrandom.h"

#include <cmath>

namespace mbscope {

namespace {

quint64 splitmix64(quint64 &state)
{
    quint64 z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

constexpr quint64 rotl(quint64 x, int k)
{
    return (x << k) | (x >> (64 - k));
}

} // namespace

void SimRandom::reseed(quint64 seed)
{
    quint64 state = seed;
    for (quint64 &s : m_s)
        s = splitmix64(state);
}

quint64 SimRandom::next()
{
    const quint64 result = rotl(m_s[1] * 5, 7) * 9;
    const quint64 t = m_s[1] << 17;
    m_s[2] ^= m_s[0];
    m_s[3] ^= m_s[1];
    m_s[1] ^= m_s[2];
    m_s[0] ^= m_s[3];
    m_s[2] ^= t;
    m_s[3] = rotl(m_s[3], 45);
    return result;
}

double SimRandom::uniform()
{
    return double(next() >> 11) * 0x1.0p-53;
}

quint64 SimRandom::below(quint64 bound)
{
    if (bound <= 1)
        return 0;
    // Rejection of the top partial interval (at most half of the draws, usually none).
    const quint64 limit = ~quint64(0) - (~quint64(0) % bound + 1) % bound;
    quint64 x = next();
    while (x > limit)
        x = next();
    return x % bound;
}

bool SimRandom::chance(double p)
{
    const double u = uniform();
    return u < p;
}

double SimRandom::normal(double mean, double stddev)
{
    double u = 0;
    double v = 0;
    double s = 0;
    do {
        u = uniform(-1.0, 1.0);
        v = uniform(-1.0, 1.0);
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    return mean + stddev * u * std::sqrt(-2.0 * std::log(s) / s);
}

double SimRandom::exponential(double mean)
{
    // 1 - u lies in (0, 1], so the logarithm is finite.
    return -mean * std::log(1.0 - uniform());
}

double SimRandom::logNormal(double mean, double stddev)
{
    const double sigma2 = mean > 0 ? std::log1p((stddev / mean) * (stddev / mean)) : 0.0;
    const double z = normal(0.0, 1.0); // drawn either way, so that the sequence does not depend on mean
    if (!(mean > 0))
        return 0.0;
    return std::exp(std::log(mean) - sigma2 / 2 + std::sqrt(sigma2) * z);
}

quint64 SimRandom::poisson(double lambda)
{
    if (!(lambda > 0))
        return 0;
    if (lambda < 10) {
        // Count uniforms until their product falls below e^-lambda (Knuth, TAOCP 3.4.1).
        const double limit = std::exp(-lambda);
        quint64 k = 0;
        double product = uniform();
        while (product > limit) {
            ++k;
            product *= uniform();
        }
        return k;
    }
    // PTRS: W. Hoermann, "The transformed rejection method for generating Poisson random
    // variables", Insurance: Mathematics and Economics 12 (1993) 39-45.
    const double slam = std::sqrt(lambda);
    const double loglam = std::log(lambda);
    const double b = 0.931 + 2.53 * slam;
    const double a = -0.059 + 0.02483 * b;
    const double invalpha = 1.1239 + 1.1328 / (b - 3.4);
    const double vr = 0.9277 - 3.6224 / (b - 2);
    for (;;) {
        const double u = uniform() - 0.5;
        const double v = uniform();
        const double us = 0.5 - std::fabs(u);
        const double k = std::floor((2 * a / us + b) * u + lambda + 0.43);
        if (us >= 0.07 && v <= vr && k >= 0)
            return quint64(k);
        if (k < 0 || (us < 0.013 && v > us))
            continue;
        if (std::log(v) + std::log(invalpha) - std::log(a / (us * us) + b)
            <= -lambda + k * loglam - std::lgamma(k + 1))
            return quint64(k);
    }
}

quint64 SimRandom::derive(quint64 seed, quint64 a, quint64 b, quint64 c)
{
    quint64 state = seed;
    quint64 h = splitmix64(state);
    for (quint64 label : {a, b, c}) {
        state = h ^ label;
        h = splitmix64(state);
    }
    return h;
}

} // namespace mbscope
