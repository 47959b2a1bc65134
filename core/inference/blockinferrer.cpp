#include "blockinferrer.h"

#include "scaleinferrer.h"
#include "typeinferrer.h"
#include "wordseries.h"

#include "protocol/registervalue.h"

#include <QtCore/QSet>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <span>

namespace mbscope {

ValueKind BlockInferrer::kindOf(const QList<double> &values, const QList<quint16> &words, QString *why)
{
    if (WordSeries::isConstant(values)) {
        *why = QStringLiteral("the same in all %1 samples").arg(values.size());
        return ValueKind::Constant;
    }
    int ups = 0;
    int downs = 0;
    for (qsizetype i = 1; i < values.size(); ++i) {
        if (values.at(i) > values.at(i - 1))
            ++ups;
        else if (values.at(i) < values.at(i - 1))
            ++downs;
    }
    if (downs <= 1 && ups >= 3 && ups > 4 * downs) {
        *why = downs == 0 ? QStringLiteral("grew %1 times, never fell").arg(ups)
                          : QStringLiteral("grew %1 times, fell once (a wrap)").arg(ups);
        return ValueKind::Counter;
    }
    if (!words.isEmpty()) {
        QSet<quint16> distinct(words.cbegin(), words.cend());
        bool bitFlips = true;
        bool highBit = false;
        for (qsizetype i = 1; i < words.size(); ++i) {
            const quint16 x = words.at(i) ^ words.at(i - 1);
            if (x == 0)
                continue;
            if (std::popcount(unsigned(x)) > 2)
                bitFlips = false;
            if (x >= 4)
                highBit = true;
        }
        const bool zeroOne = distinct.size() == 2 && distinct.contains(0) && distinct.contains(1);
        if (bitFlips && distinct.size() <= 4 && (highBit || zeroOne)) {
            *why = QStringLiteral("%1 distinct values, each change one or two bits flipping").arg(distinct.size());
            return ValueKind::Status;
        }
    }
    *why = QStringLiteral("rose %1 and fell %2 times").arg(ups).arg(downs);
    return ValueKind::Measurement;
}

QList<ValueGuess> BlockInferrer::infer(const BlockSamples &block)
{
    QList<ValueGuess> guesses;
    if (block.samples.isEmpty())
        return guesses;
    if (block.isBits()) {
        for (int i = 0; i < block.count(); ++i) {
            const QList<quint16> column = block.column(i);
            QList<double> values;
            for (const quint16 w : column)
                values.append(w ? 1.0 : 0.0);
            ValueGuess g;
            g.function = block.function;
            g.address = quint16(block.address + i);
            g.bit = true;
            g.confidence = 1;
            g.kind = WordSeries::isConstant(column) ? ValueKind::Constant : ValueKind::Status;
            g.evidence = g.kind == ValueKind::Constant ? QStringLiteral("bit: %1 in all %2 samples").arg(column.value(0)).arg(column.size())
                                                       : QStringLiteral("bit: changed %1 times").arg(WordSeries::totalVariation(column));
            g.last = values.constLast();
            g.minimum = *std::min_element(values.cbegin(), values.cend());
            g.maximum = *std::max_element(values.cbegin(), values.cend());
            g.lastText = column.constLast() ? QStringLiteral("1") : QStringLiteral("0");
            g.lastWords = {column.constLast()};
            guesses.append(g);
        }
        return guesses;
    }

    for (const TypedField &f : TypeInferrer::infer(block)) {
        ValueGuess g;
        g.function = block.function;
        g.address = quint16(block.address + f.offset);
        g.registers = f.registers;
        g.format = f.format;
        g.text = f.text;
        g.confidence = f.confidence;
        g.evidence = f.evidence;
        for (int k = 0; k < f.registers; ++k)
            g.lastWords.append(block.samples.constLast().value(f.offset + k));
        QString why;
        if (f.text) {
            bool still = true;
            for (int k = 0; k < f.registers; ++k)
                still = still && WordSeries::isConstant(block.column(f.offset + k));
            g.kind = still ? ValueKind::Constant : ValueKind::Measurement;
            why = still ? QStringLiteral("the same in all %1 samples").arg(block.samples.size()) : QStringLiteral("changed");
            g.lastText = RegisterValue::asciiText(std::span<const quint16>(g.lastWords.constData(), size_t(g.lastWords.size())), false);
            while (g.lastText.endsWith(QLatin1String("\\x00")))
                g.lastText.chop(4);
        } else {
            const QList<double> values = WordSeries::decode(block, f.offset, f.format);
            g.kind = kindOf(values, f.registers == 1 ? block.column(f.offset) : QList<quint16>(), &why);
            if (g.kind == ValueKind::Status)
                g.format = RegisterFormat(RegisterType::Binary16);
        }
        g.evidence += QStringLiteral("; %1: %2").arg(valueKindName(g.kind), why);
        guesses.append(g);
    }
    ScaleInferrer::apply(guesses, block);
    return guesses;
}

QList<QList<ValueGuess>> BlockInferrer::inferUnit(const QList<BlockSamples> &blocks)
{
    QList<ValueGuess> all;
    QList<qsizetype> sizes;
    for (const BlockSamples &b : blocks) {
        const QList<ValueGuess> guesses = infer(b);
        sizes.append(guesses.size());
        all += guesses;
    }
    // Setpoints beside temperatures, across the unit's blocks.
    ScaleInferrer::applyNeighbours(all);
    QList<QList<ValueGuess>> out;
    qsizetype at = 0;
    for (const qsizetype n : std::as_const(sizes)) {
        out.append(all.mid(at, n));
        at += n;
    }
    return out;
}

} // namespace mbscope
