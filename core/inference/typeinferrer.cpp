#include "typeinferrer.h"

#include "wordseries.h"

#include <QtCore/QMap>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

constexpr RegisterOrder kOrders[] = {RegisterOrder::ABCD, RegisterOrder::CDAB, RegisterOrder::BADC, RegisterOrder::DCBA};

// Scores per register of each reading: a value read as a wide type must do better than the same
// registers read one by one (1.0 each).
constexpr double kSingle = 1.0;
constexpr double kFloatMoving = 2.0;
constexpr double kFloatStill = 1.3;
constexpr double kIntStrong = 2.0;
constexpr double kIntMedium = 1.4;
constexpr double kIntWeak = 1.05;

bool isPrintable(int byte)
{
    return byte >= 0x20 && byte <= 0x7E;
}

// A register of text: two printable bytes, or a printable one and a NUL (the end of an odd string).
bool isTextWord(quint16 w)
{
    const int hi = w >> 8;
    const int lo = w & 0xFF;
    return isPrintable(hi) && (isPrintable(lo) || lo == 0);
}

struct Candidate {
    int registers = 1;
    RegisterFormat format;
    double score = 0; // the whole value's, -1: not possible
    double confidence = 0.5;
    QString evidence;
};

// Everything the readings of one block need, cached by (offset, type, order).
class BlockReader
{
public:
    explicit BlockReader(const BlockSamples &block) : m_block(block) {}

    // The words of the value at offset in natural significance (most significant first), each
    // register's bytes swapped when the order says so.
    [[nodiscard]] QList<QList<quint16>> words(int offset, int count, RegisterOrder order) const
    {
        QList<QList<quint16>> out(count);
        const bool swapWords = order == RegisterOrder::CDAB || order == RegisterOrder::DCBA;
        const bool swapBytes = order == RegisterOrder::BADC || order == RegisterOrder::DCBA;
        for (int k = 0; k < count; ++k) {
            const int at = offset + (swapWords ? count - 1 - k : k);
            QList<quint16> column = m_block.column(at);
            if (swapBytes) {
                for (quint16 &w : column)
                    w = quint16((w << 8) | (w >> 8));
            }
            out[k] = column;
        }
        return out;
    }

    [[nodiscard]] Candidate floating(int offset, RegisterType type, RegisterOrder order) const
    {
        const RegisterFormat format(type, order);
        const int n = format.registerCount();
        Candidate c{n, format, -1, 0, {}};
        const QList<double> values = WordSeries::decode(m_block, offset, format);
        if (values.isEmpty())
            return c;
        bool allZeroWords = true;
        for (int k = 0; k < n; ++k)
            allZeroWords = allZeroWords && WordSeries::isConstant(m_block.column(offset + k), 0);
        if (allZeroWords)
            return c; // 0.0 and two zero registers look alike: decided by the neighbours
        for (const double v : values) {
            if (!TypeInferrer::plausibleFloat(v))
                return c;
        }
        const auto [low, high] = std::minmax_element(values.cbegin(), values.cend());
        const bool moving = *low != *high;
        const QList<QList<quint16>> w = words(offset, n, order);
        if (moving) {
            // A measured float's least significant word is mantissa noise: it moves. A float whose
            // low words stay put while it moves is integers read as one (a count beside a 0).
            if (WordSeries::isConstant(w.constLast()))
                return c;
            if (n == 4 && WordSeries::isConstant(w.at(2)))
                return c;
            // Measurements move smoothly: the binary exponent rarely jumps by 2 or more. Small
            // integers read with their bytes swapped land in the exponent and jump at every step.
            if (!WordSeries::smoothExponent(values))
                return c;
        } else if (WordSeries::significantDigits(*low, n == 2) > 6) {
            // A value that never moves is a setting or a constant: a round number.
            return c;
        }
        c.score = n * (moving ? kFloatMoving : kFloatStill);
        c.confidence = moving ? 0.9 : 0.6;
        // The same words as an integer: how far the least significant word jumps.
        const int jumpBits = WordSeries::largestJumpBits(w.constLast());
        c.evidence = QStringLiteral("%1 %2: %3 samples all finite, %4%5")
                         .arg(format.typeName(), format.orderName())
                         .arg(values.size())
                         .arg(moving ? QStringLiteral("%1 to %2").arg(WordSeries::number(*low), WordSeries::number(*high))
                                     : QStringLiteral("always %1").arg(WordSeries::number(*low)))
                         .arg(moving ? WordSeries::smoothness(values) : QString());
        if (moving && jumpBits >= 8)
            c.evidence += QStringLiteral("; as %1 the same words jump by 2^%2")
                              .arg(n == 2 ? QStringLiteral("u32") : QStringLiteral("u64"))
                              .arg(jumpBits);
        return c;
    }

    // Whether (offset, offset + 1) read in order could be one 32-bit integer at all.
    [[nodiscard]] WordSeries::Strength pairStrength(int offset, RegisterOrder order) const
    {
        if (offset < 0 || offset + 2 > m_block.count())
            return WordSeries::Strength::None;
        const QList<QList<quint16>> w = words(offset, 2, order);
        return WordSeries::pairEvidence(w.at(0), w.at(1)).strength;
    }

    // A high word that stays 0 says little alone; in a run of three or more values laid out alike
    // (every other register 0 beside a moving one) it says the block is of 32-bit values.
    [[nodiscard]] bool inWideRun(int offset, RegisterOrder order) const
    {
        int run = 1;
        for (int at = offset - 2; pairStrength(at, order) != WordSeries::Strength::None; at -= 2)
            ++run;
        for (int at = offset + 2; pairStrength(at, order) != WordSeries::Strength::None; at += 2)
            ++run;
        return run >= 3;
    }

    // A 32- or 64-bit integer: the high words must behave as high words.
    [[nodiscard]] Candidate integer(int offset, int n, RegisterOrder order, bool haveHint) const
    {
        Candidate c{n, RegisterFormat(n == 2 ? RegisterType::UInt32 : RegisterType::UInt64, order), -1, 0, {}};
        const QList<QList<quint16>> w = words(offset, n, order);
        const QList<quint16> &lo = w.constLast();
        const QList<quint16> &hi = w.at(n - 2);
        if (n == 4) {
            // The top two words: still, and not both 0 (else two u32 values read as well).
            if (!WordSeries::isConstant(w.at(0)) || !WordSeries::isConstant(w.at(1)))
                return c;
            if (w.at(0).constFirst() == 0 && w.at(1).constFirst() == 0)
                return c;
            if (w.at(0).constFirst() > 0x00FF && w.at(0).constFirst() != 0xFFFF)
                return c;
        }
        const WordSeries::PairEvidence e = WordSeries::pairEvidence(hi, lo);
        const QString orderText = RegisterFormat(c.format.type(), order).orderName();
        double perRegister = 0;
        switch (e.strength) {
        case WordSeries::Strength::Strong: perRegister = kIntStrong; c.confidence = 0.85; break;
        case WordSeries::Strength::Medium:
            // A still, small high word beside a moving one is as often a setting beside a
            // measurement: one value only when the low word counts up, or among wide values.
            if (!e.negative && !WordSeries::countsUp(lo) && !(haveHint && n == 2 && inWideRun(offset, order)))
                return c;
            perRegister = kIntMedium;
            c.confidence = 0.65;
            break;
        case WordSeries::Strength::Weak:
            if (!haveHint || n != 2 || !inWideRun(offset, order))
                return c;
            perRegister = kIntWeak;
            c.confidence = 0.45;
            break;
        case WordSeries::Strength::None:
            return c;
        }
        if (n == 4)
            perRegister += 0.05; // one 64-bit value over two 32-bit readings of the same strength
        // The right byte order makes the low word move in small steps; read with its bytes
        // swapped the same word jumps by hundreds.
        QList<quint16> swapped = lo;
        for (quint16 &x : swapped)
            x = quint16((x << 8) | (x >> 8));
        if (WordSeries::totalVariation(lo) <= WordSeries::totalVariation(swapped))
            perRegister += 0.02;
        const bool isSigned = e.negative;
        c.format = RegisterFormat(n == 2 ? (isSigned ? RegisterType::Int32 : RegisterType::UInt32)
                                         : (isSigned ? RegisterType::Int64 : RegisterType::UInt64),
                                  order);
        c.score = n * perRegister;
        c.evidence = QStringLiteral("%1 %2: %3").arg(c.format.typeName(), orderText, e.text);
        return c;
    }

private:
    const BlockSamples &m_block;
};

struct Cover {
    double score = 0;
    QList<TypedField> fields;
};

// The best cover of [first, end) by values read in one order (dynamic programming from the end).
Cover bestCover(const BlockReader &reader, int first, int end, RegisterOrder order, bool haveHint)
{
    const int n = end - first;
    QList<double> best(n + 1, 0.0);
    QList<Candidate> choice(n);
    for (int i = n - 1; i >= 0; --i) {
        const int at = first + i;
        Candidate single{1, RegisterFormat(RegisterType::UInt16), kSingle, 0.5, {}};
        best[i] = single.score + best[i + 1];
        choice[i] = single;
        QList<Candidate> wide;
        if (i + 2 <= n) {
            wide.append(reader.floating(at, RegisterType::Float32, order));
            wide.append(reader.integer(at, 2, order, haveHint));
        }
        if (i + 4 <= n) {
            wide.append(reader.floating(at, RegisterType::Float64, order));
            wide.append(reader.integer(at, 4, order, haveHint));
        }
        for (const Candidate &c : std::as_const(wide)) {
            if (c.score < 0)
                continue;
            // Values start at even offsets of a run far more often than not.
            const double aligned = (i % 2 == 0) ? 0.01 : 0.0;
            const double total = c.score + aligned + best[i + c.registers];
            if (total > best[i] + 1e-9) {
                best[i] = total;
                choice[i] = c;
            }
        }
    }
    Cover cover;
    cover.score = best[0];
    for (int i = 0; i < n;) {
        const Candidate &c = choice[i];
        cover.fields.append(TypedField{first + i, c.registers, c.format, false, c.confidence, c.evidence});
        i += c.registers;
    }
    return cover;
}

// Strings: runs of still, printable registers (at least three, or two then a NUL register),
// with the NUL registers after them up to a length of a multiple of four registers.
QList<TypedField> findStrings(const BlockSamples &block)
{
    QList<TypedField> out;
    const int n = block.count();
    int i = 0;
    while (i < n) {
        int j = i;
        int letters = 0;
        int chars = 0;
        while (j < n && WordSeries::isConstant(block.column(j)) && isTextWord(block.column(j).value(0))) {
            const quint16 w = block.column(j).value(0);
            for (const int b : {w >> 8, w & 0xFF}) {
                letters += (QChar(b).isLetterOrNumber() || b == ' ') ? 1 : 0;
                chars += b != 0 ? 1 : 0;
            }
            if ((w & 0xFF) == 0) {
                ++j;
                break;
            }
            ++j;
        }
        const int textRegisters = j - i;
        int zeros = 0;
        while (j + zeros < n && WordSeries::isConstant(block.column(j + zeros), 0))
            ++zeros;
        const bool ok = block.samples.size() > 0
                        && (textRegisters >= 3 || (textRegisters >= 2 && zeros > 0))
                        && letters * 2 >= chars;
        if (!ok) {
            ++i;
            continue;
        }
        int length = textRegisters + zeros;
        // Fixed-length fields: keep the padding to a multiple of four registers when that is possible.
        if (length % 4 != 0 && (length / 4) * 4 >= textRegisters + (textRegisters % 2))
            length = std::max(textRegisters, (length / 4) * 4);
        QString shown;
        for (int k = i; k < i + textRegisters; ++k) {
            const quint16 w = block.column(k).value(0);
            shown += QChar(w >> 8);
            if (w & 0xFF)
                shown += QChar(w & 0xFF);
        }
        out.append(TypedField{i, length, RegisterFormat(RegisterType::Ascii), true, 0.9,
                              QStringLiteral("ascii: %1 registers still in every sample, printable text \"%2\"%3")
                                  .arg(textRegisters)
                                  .arg(shown)
                                  .arg(length > textRegisters ? QStringLiteral(" then %1 NUL registers").arg(length - textRegisters)
                                                              : QString())});
        i += length;
    }
    return out;
}

// Single registers: u16, i16 when the values sit around 0 with the sign bit set, byte-swapped when
// the bytes read the other way change far more smoothly.
TypedField single(const BlockSamples &block, int offset)
{
    const QList<quint16> column = block.column(offset);
    TypedField f{offset, 1, RegisterFormat(RegisterType::UInt16), false, 0.5, {}};
    QList<quint16> swapped = column;
    for (quint16 &w : swapped)
        w = quint16((w << 8) | (w >> 8));
    const double straight = WordSeries::totalVariation(column);
    const double crossed = WordSeries::totalVariation(swapped);
    const bool byteSwap = straight > 0 && crossed * 16 < straight;
    const QList<quint16> &words = byteSwap ? swapped : column;
    bool high = false;
    bool nearZero = true;
    for (const quint16 w : words) {
        high = high || w >= 0x8000;
        nearZero = nearZero && (w < 0x4000 || w >= 0xC000);
    }
    const bool sentinel = WordSeries::isConstant(words, 0x8000);
    const bool allOnes = WordSeries::isConstant(words, 0xFFFF); // a u16's "not implemented", or -1
    const bool isSigned = ((high && nearZero) || sentinel) && !allOnes;
    f.format = RegisterFormat(isSigned ? RegisterType::Int16 : RegisterType::UInt16,
                              byteSwap ? RegisterOrder::BADC : RegisterOrder::ABCD);
    if (byteSwap) {
        f.confidence = 0.7;
        f.evidence = QStringLiteral("%1 BA: read low byte first the value changes by %2 in all, high byte first by %3")
                         .arg(f.format.typeName()).arg(crossed).arg(straight);
    } else if (allOnes) {
        f.confidence = 0.4;
        f.evidence = QStringLiteral("u16: FFFF in every sample, the usual 'not implemented' of an unsigned register (or -1)");
    } else if (sentinel) {
        f.confidence = 0.5;
        f.evidence = QStringLiteral("i16: 8000 in every sample, the usual 'not available' of a signed register");
    } else if (isSigned) {
        f.confidence = 0.7;
        f.evidence = QStringLiteral("i16: values with the sign bit set read as small negative numbers");
    } else {
        f.confidence = WordSeries::isConstant(column) ? 0.4 : 0.6;
        f.evidence = QStringLiteral("u16: no wider reading of these registers fits better");
    }
    return f;
}

} // namespace

bool TypeInferrer::plausibleFloat(double value)
{
    if (!std::isfinite(value))
        return false;
    const double m = std::fabs(value);
    return m == 0 || (m >= 1e-5 && m <= 1e9);
}

QList<TypedField> TypeInferrer::infer(const BlockSamples &block)
{
    QList<TypedField> out;
    const int n = block.count();
    if (n <= 0 || block.samples.isEmpty() || block.isBits())
        return out;
    QList<TypedField> strings = findStrings(block);
    // The SunSpec marker "SunS" (0x53756E53, a u32) opens a SunSpec map: a known constant.
    for (int i = 0; i + 1 < n; ++i) {
        if (!WordSeries::isConstant(block.column(i), 0x5375) || !WordSeries::isConstant(block.column(i + 1), 0x6E53))
            continue;
        const bool inString = std::any_of(strings.cbegin(), strings.cend(), [i](const TypedField &s) {
            return i + 1 >= s.offset && i < s.offset + s.registers;
        });
        if (!inString)
            strings.append(TypedField{i, 2, RegisterFormat(RegisterType::UInt32), false, 0.95,
                                      QStringLiteral("u32 ABCD: 0x53756E53, the SunSpec marker \"SunS\" that opens a SunSpec map")});
    }
    std::sort(strings.begin(), strings.end(), [](const TypedField &a, const TypedField &b) { return a.offset < b.offset; });

    // The free runs between strings.
    QList<QPair<int, int>> runs;
    int at = 0;
    for (const TypedField &s : strings) {
        if (s.offset > at)
            runs.append({at, s.offset});
        at = s.offset + s.registers;
    }
    if (at < n)
        runs.append({at, n});

    // The device's order: the one whose covers score best. Integers with only a weak sign of
    // being wide (a high word that stays 0) count only once an order is known from strong ones.
    const BlockReader reader(block);
    RegisterOrder bestOrder = RegisterOrder::ABCD;
    double bestScore = -1;
    for (const RegisterOrder order : kOrders) {
        double score = order == RegisterOrder::ABCD ? 0.001 : 0.0;
        for (const auto &[first, end] : std::as_const(runs))
            score += bestCover(reader, first, end, order, false).score;
        if (score > bestScore + 1e-9) {
            bestScore = score;
            bestOrder = order;
        }
    }
    // Whether anything wide was found at all in that order: a hint for the weak cases.
    bool haveHint = false;
    for (const auto &[first, end] : std::as_const(runs)) {
        for (const TypedField &f : bestCover(reader, first, end, bestOrder, false).fields)
            haveHint = haveHint || f.registers > 1;
    }

    QList<TypedField> fields = strings;
    for (const auto &[first, end] : std::as_const(runs)) {
        for (TypedField f : bestCover(reader, first, end, bestOrder, haveHint).fields) {
            if (f.registers == 1)
                f = single(block, f.offset);
            fields.append(f);
        }
    }
    std::sort(fields.begin(), fields.end(), [](const TypedField &a, const TypedField &b) { return a.offset < b.offset; });

    // Registers that stay 0 among two-register values of one format: values of that format too.
    QMap<QString, int> wideRegisters;
    int numericRegisters = 0;
    for (const TypedField &f : std::as_const(fields)) {
        if (f.text)
            continue;
        numericRegisters += f.registers;
        if (f.registers == 2)
            wideRegisters[f.format.name()] += 2;
    }
    QString dominant;
    int dominantCount = 0;
    for (auto it = wideRegisters.cbegin(); it != wideRegisters.cend(); ++it) {
        if (it.value() > dominantCount) {
            dominant = it.key();
            dominantCount = it.value();
        }
    }
    if (!dominant.isEmpty() && dominantCount * 2 >= numericRegisters) {
        RegisterFormat format = RegisterFormat::parse(dominant).format;
        if (format.isSigned())
            format = RegisterFormat(RegisterType::UInt32, format.order());
        QList<TypedField> merged;
        for (int i = 0; i < fields.size(); ++i) {
            const TypedField &f = fields.at(i);
            const bool zero = f.registers == 1 && !f.text && WordSeries::isConstant(block.column(f.offset), 0);
            const bool nextZero = i + 1 < fields.size() && fields.at(i + 1).registers == 1 && !fields.at(i + 1).text
                                  && fields.at(i + 1).offset == f.offset + 1
                                  && WordSeries::isConstant(block.column(f.offset + 1), 0);
            if (zero && nextZero) {
                merged.append(TypedField{f.offset, 2, format, false, 0.35,
                                         QStringLiteral("%1 %2: 0 in every sample, taken as the block's other values are")
                                             .arg(format.typeName(), format.orderName())});
                ++i;
                continue;
            }
            merged.append(f);
        }
        fields = merged;
    }
    // A run of four or more registers that stay 0, of even length, in a block that has 32-bit
    // integers: taken two by two as such integers in the block's order (flags and counters not
    // started; a guess, said with little confidence).
    bool wideIntegers = false;
    for (const TypedField &f : std::as_const(fields))
        wideIntegers = wideIntegers || (f.registers == 2 && !f.text && !f.format.isFloat());
    if (wideIntegers) {
        QList<TypedField> merged;
        for (int i = 0; i < fields.size();) {
            int j = i;
            while (j < fields.size() && fields.at(j).registers == 1 && !fields.at(j).text
                   && fields.at(j).offset == fields.at(i).offset + (j - i)
                   && WordSeries::isConstant(block.column(fields.at(j).offset), 0))
                ++j;
            const int run = j - i;
            if (run >= 4 && run % 2 == 0) {
                const RegisterFormat format(RegisterType::UInt32, bestOrder);
                for (int k = i; k < j; k += 2)
                    merged.append(TypedField{fields.at(k).offset, 2, format, false, 0.3,
                                             QStringLiteral("%1 %2: one of %3 registers that stay 0, taken two by two as the block's other 32-bit integers")
                                                 .arg(format.typeName(), format.orderName()).arg(run)});
                i = j;
                continue;
            }
            const int end = std::max(j, i + 1); // a shorter or odd run stays as it is, whole
            for (; i < end; ++i)
                merged.append(fields.at(i));
        }
        fields = merged;
    }
    return fields;
}

} // namespace mbscope
