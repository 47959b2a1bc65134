#include "scaleinferrer.h"

#include "powerrelations.h"
#include "wordseries.h"

#include <algorithm>
#include <string_view>
#include <optional>
#include <cmath>
#include <cstdlib>

namespace mbscope {

namespace {

// A u16 guess re-read as i16 because it is a temperature: the type and its evidence say so (the
// evidence said "u16: ..." beside the type i16).
void readSigned(ValueGuess &g)
{
    g.format = RegisterFormat(RegisterType::Int16, g.format.order());
    if (g.evidence.startsWith(QLatin1String("u16:"))) {
        const qsizetype end = g.evidence.indexOf(QLatin1Char(';'));
        const QString why = g.evidence.mid(4, end < 0 ? -1 : end - 4);
        g.evidence = QStringLiteral("i16, as a temperature has a sign (as u16:%1)").arg(why) + (end < 0 ? QString() : g.evidence.mid(end));
    }
}


struct Quantity {
    const char *name;
    const char *unit;
    double low;
    double high;
    double maxRelativeSpread; // (max - min) / max |value| must stay under this; 0: any
};

// In the order tried at each power of ten.
constexpr Quantity kQuantities[] = {
    {"frequency", "Hz", 45, 65, 0.01},
    {"voltage", "V", 207, 253, 0.05},
    {"voltage", "V", 380, 420, 0.05},
    {"power factor", "", 0.3, 1.0, 0.5},
    {"temperature", "degC", -40, 90, 0},
};

constexpr int kExponents[] = {1, 2, 0, 3}; // tenths first: the most common device scale

// Temperatures are sent in tenths of a degree by nearly every device, in one register: read as
// one only then (a power near 0 in hundredths reads as a temperature too).
const Quantity *recognise(double low, double high, int exponent, int registers)
{
    for (const Quantity &q : kQuantities) {
        if (q.unit == std::string_view("degC") && (exponent != 1 || registers != 1))
            continue;
        if (low < q.low || high > q.high)
            continue;
        const double largest = std::max(std::fabs(low), std::fabs(high));
        if (q.maxRelativeSpread > 0 && largest > 0 && (high - low) / largest > q.maxRelativeSpread)
            continue;
        return &q;
    }
    return nullptr;
}

QList<double> rawValues(const ValueGuess &g, const BlockSamples &block)
{
    return WordSeries::decode(block, g.address - block.address, g.format);
}

bool scalable(const ValueGuess &g)
{
    return !g.text && !g.bit && !g.format.isFloat() && g.kind != ValueKind::Status;
}

// A register still at -6..0 as i16: a scale factor, when it follows moving values.
std::optional<int> scaleExponent(const ValueGuess &g, const BlockSamples &block)
{
    if (g.text || g.bit || g.registers != 1 || g.kind != ValueKind::Constant)
        return std::nullopt;
    const qint16 v = qint16(block.column(g.address - block.address).value(0));
    if (v >= -6 && v <= 0)
        return int(v);
    return std::nullopt;
}

} // namespace

void ScaleInferrer::apply(QList<ValueGuess> &guesses, const BlockSamples &block)
{
    // Scale-factor registers: each scales the values before it, back to the previous one. Only
    // registers after moving values count, and only when two or more are not 0.
    QList<int> factors;
    int nonZero = 0;
    bool sawMoving = false;
    for (qsizetype i = 0; i < guesses.size(); ++i) {
        const ValueGuess &g = guesses.at(i);
        const std::optional<int> exponent = scaleExponent(g, block);
        if (exponent && sawMoving) {
            factors.append(int(i));
            nonZero += *exponent != 0 ? 1 : 0;
            sawMoving = false;
        } else if (scalable(g) && g.kind != ValueKind::Constant) {
            sawMoving = true;
        }
    }
    if (nonZero >= 2) {
        qsizetype from = 0;
        for (const int at : std::as_const(factors)) {
            const ValueGuess &sf = guesses.at(at);
            const int exponent = *scaleExponent(sf, block);
            // The values it scales: the scalable ones right before it, back to the previous
            // factor or anything else, without the still ones that lead the run (ids, lengths).
            qsizetype first = at;
            while (first > from && scalable(guesses.at(first - 1)))
                --first;
            while (first < at && guesses.at(first).kind == ValueKind::Constant)
                ++first;
            for (qsizetype i = first; i < at; ++i) {
                ValueGuess &g = guesses[i];
                g.scale = std::pow(10.0, exponent);
                g.scaleRegister = sf.address;
                g.scaleEvidence = QStringLiteral("scale-factor register at %1 holds %2 (x 10^%2)").arg(sf.address).arg(exponent);
                g.scaleConfidence = 0.9;
            }
            guesses[at].format = RegisterFormat(RegisterType::Int16);
            guesses[at].quantity = QStringLiteral("scale factor");
            guesses[at].confidence = 0.8;
            guesses[at].evidence = QStringLiteral("i16 scale factor: %1 in every sample, right after the values it scales").arg(exponent);
            from = at + 1;
        }
    }

    for (ValueGuess &g : guesses) {
        if (g.text || g.bit)
            continue;
        const QList<double> raw = rawValues(g, block);
        if (raw.isEmpty())
            continue;
        const auto [lowIt, highIt] = std::minmax_element(raw.cbegin(), raw.cend());
        const double low = *lowIt;
        const double high = *highIt;
        if (g.scaleRegister < 0 && scalable(g) && g.kind == ValueKind::Measurement) {
            for (const int k : kExponents) {
                const double s = std::pow(10.0, -k);
                // An unsigned register read as signed for temperatures: the same numbers while positive.
                const Quantity *q = recognise(low * s, high * s, k, g.registers);
                if (!q)
                    continue;
                g.scale = s;
                g.quantity = QString::fromLatin1(q->name);
                g.unit = QString::fromLatin1(q->unit);
                g.scaleConfidence = 0.8;
                g.scaleEvidence = QStringLiteral("raw %1 to %2 x %3 = %4 to %5 %6: reads as %7")
                                      .arg(WordSeries::number(low), WordSeries::number(high), WordSeries::number(s),
                                           WordSeries::number(low * s), WordSeries::number(high * s), g.unit, g.quantity)
                                      .trimmed();
                if (g.quantity == QLatin1String("temperature") && g.format.type() == RegisterType::UInt16)
                    readSigned(g); // temperatures have a sign
                break;
            }
        } else if (g.format.isFloat() && g.kind == ValueKind::Measurement) {
            if (const Quantity *q = recognise(low, high, 0, g.registers)) {
                g.quantity = QString::fromLatin1(q->name);
                g.unit = QString::fromLatin1(q->unit);
                g.scaleConfidence = 0.8;
                g.scaleEvidence = QStringLiteral("%1 to %2: reads as %3").arg(WordSeries::number(low), WordSeries::number(high), g.quantity);
            }
        } else if (g.scaleRegister >= 0) {
            const Quantity *q = recognise(low * g.scale, high * g.scale, int(std::lround(-std::log10(g.scale))), g.registers);
            if (q && g.kind == ValueKind::Measurement) {
                g.quantity = QString::fromLatin1(q->name);
                g.unit = QString::fromLatin1(q->unit);
                if (g.quantity == QLatin1String("temperature") && g.format.type() == RegisterType::UInt16)
                    readSigned(g);
            }
        }
    }

    PowerRelations::apply(guesses, block);

    for (ValueGuess &g : guesses) {
        if (g.text || g.bit)
            continue;
        const QList<double> raw = rawValues(g, block);
        if (raw.isEmpty())
            continue;
        const auto [lowIt, highIt] = std::minmax_element(raw.cbegin(), raw.cend());
        const double low = *lowIt;
        const double high = *highIt;
        QList<double> values = raw;
        for (double &v : values)
            v *= g.scale;
        g.minimum = low * g.scale;
        g.maximum = high * g.scale;
        g.last = values.constLast();
        g.typicalStep = WordSeries::medianStep(values);
        g.lastText = WordSeries::number(g.last);
    }
}

void ScaleInferrer::applyNeighbours(QList<ValueGuess> &guesses)
{
    // Temperatures in tenths of a degree, by table, and whether any was seen.
    int temperatures = 0;
    for (const ValueGuess &g : guesses)
        temperatures += (g.quantity == QLatin1String("temperature") && std::fabs(g.scale - 0.1) < 1e-12) ? 1 : 0;
    if (temperatures == 0)
        return;
    for (ValueGuess &g : guesses) {
        if (g.text || g.bit || g.registers != 1 || g.kind != ValueKind::Constant || g.scale != 1 || g.scaleRegister >= 0
            || g.format.isFloat() || g.quantity == QLatin1String("scale factor"))
            continue;
        const quint16 raw = g.lastWords.value(0);
        if (raw < 50 || raw > 900)
            continue; // 5.0 to 90.0 degrees: a setpoint's range
        // A still register beside temperatures of its table (16 addresses at most), or in a block
        // of still values (settings) of a device that measures temperatures in tenths.
        bool beside = false;
        bool settingsBlock = raw % 5 == 0;
        for (const ValueGuess &o : std::as_const(guesses)) {
            if (o.function != g.function)
                continue;
            const bool temperature = o.quantity == QLatin1String("temperature") && std::fabs(o.scale - 0.1) < 1e-12;
            if (temperature && std::abs(int(o.address) - int(g.address)) <= 16)
                beside = true;
            if (std::abs(int(o.address) - int(g.address)) <= 8 && (o.kind != ValueKind::Constant || o.text))
                settingsBlock = false;
        }
        if (!beside && !(settingsBlock && temperatures >= 2))
            continue;
        g.scale = 0.1;
        g.unit = QStringLiteral("degC");
        g.quantity = QStringLiteral("temperature");
        readSigned(g);
        g.minimum = g.maximum = g.last = raw * 0.1;
        g.lastText = WordSeries::number(g.last);
        g.scaleConfidence = 0.5;
        g.scaleEvidence = beside ? QStringLiteral("still at raw %1; x 0.1 = %2 degC, a setpoint beside temperatures in tenths").arg(raw).arg(g.last)
                                 : QStringLiteral("still at raw %1 among settings; x 0.1 = %2 degC, as the device's temperatures").arg(raw).arg(g.last);
    }
}

} // namespace mbscope
