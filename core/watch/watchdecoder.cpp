#include "watchdecoder.h"

#include "watch/watchblock.h"

#include "protocol/registervalue.h"

#include <QtCore/QHash>

namespace mbscope {

quint32 WatchDecoder::bitFieldValue(const WatchBitField &field, quint64 raw)
{
    const quint64 mask = field.bitCount >= 32 ? 0xFFFFFFFFULL : ((1ULL << field.bitCount) - 1);
    return quint32((raw >> field.firstBit) & mask);
}

QString WatchDecoder::numberText(double value)
{
    // Ten significant digits: a scale such as 0.0048876 leaves binary noise in the last digits of
    // the product (0.32746919999999996), which no instrument measures.
    return QString::number(value, 'g', 10);
}

QList<WatchPointValue> WatchDecoder::decode(const WatchDefinition &watch, const QList<quint16> &words,
                                            const QList<bool> &bits)
{
    // The point at an address; a watch has a few points, so a scan beats a hash made each poll.
    // The last point of an address wins, as it did when this was a hash.
    const auto pointAt = [&watch](quint16 address) -> int {
        for (qsizetype i = watch.points.size() - 1; i >= 0; --i) {
            if (watch.points.at(i).address == address)
                return int(i);
        }
        return -1;
    };

    QList<WatchPointValue> values;
    if (WatchBlock::isBitFunction(watch.function)) {
        values.reserve(bits.size());
        for (int i = 0; i < bits.size(); ++i) {
            WatchPointValue v;
            v.address = quint16(watch.address + i);
            v.raw = bits.at(i) ? 1 : 0;
            v.value = double(v.raw);
            v.text = bits.at(i) ? QStringLiteral("1") : QStringLiteral("0");
            if (const int p = pointAt(v.address); p >= 0) {
                const WatchPoint &point = watch.points.at(p);
                v.point = p;
                v.name = point.name;
                v.unit = point.unit;
            }
            values.append(std::move(v));
        }
        return values;
    }

    const int perAddress = WatchBlock::wordsPerAddress(watch);
    // A FIFO's values all come from one address: they are numbered from it.
    const int addresses = int(words.size()) / perAddress;
    values.reserve(addresses);
    for (int i = 0; i < addresses;) {
        WatchPointValue v;
        v.address = quint16(watch.address + i);
        const int p = pointAt(v.address);
        const WatchPoint *point = p >= 0 ? &watch.points.at(p) : nullptr;
        RegisterFormat format = point ? WatchBlock::effectiveFormat(watch, *point)
                                      : (perAddress == 2 ? RegisterFormat(RegisterType::UInt32) : RegisterFormat());
        // Addresses the value occupies: a u32 spans two 16-bit addresses, one 32-bit Enron address.
        const int width = qMax(1, format.registerCount() / perAddress);
        if (i + width > addresses) {
            if (!point)
                break;
            // The point's registers run past the answer: its addresses are shown unnamed.
            format = perAddress == 2 ? RegisterFormat(RegisterType::UInt32) : RegisterFormat();
            point = nullptr;
        }
        const int used = point ? width : 1;
        const std::span<const quint16> registers(words.constData() + qsizetype(i) * perAddress,
                                                 std::size_t(used * perAddress));
        const RegisterValueResult decoded = RegisterValue::fromRegisters(registers, format);
        v.width = used;
        v.raw = decoded.value.bits();
        const double number = decoded.value.toDouble();
        if (point) {
            v.point = p;
            v.name = point->name;
            v.unit = point->unit;
            v.value = number * point->scale + point->offset;
            const bool scaled = point->scale != 1 || point->offset != 0;
            v.text = scaled ? numberText(v.value) : decoded.value.toText();
            for (const WatchBitField &field : point->bitFields) {
                WatchBitFieldValue b;
                b.name = field.name;
                b.value = bitFieldValue(field, v.raw);
                if (b.value < quint32(field.states.size()))
                    b.state = field.states.at(int(b.value));
                v.bitFields.append(b);
            }
        } else {
            v.value = number;
            v.text = decoded.value.toText();
        }
        values.append(std::move(v));
        i += used;
    }
    return values;
}

} // namespace mbscope
