#pragma once

#include <QtCore/QList>
#include <QtCore/QtGlobal>

namespace mbscope {

// One block of a table read many times: every sample holds count() words (registers, or bits as
// 0/1), the block's first address first. What inference works on: nothing else is known.
struct BlockSamples {
    quint8 function = 3;       // the read function: 01-04
    quint16 address = 0;
    int registerCount = 0;     // addresses in the block
    QList<QList<quint16>> samples;
    int failedReads = 0;       // reads that got no usable answer (not in samples)

    [[nodiscard]] bool isBits() const { return function <= 2; }
    [[nodiscard]] int count() const { return registerCount; }
    // The words of address index column, one per sample.
    [[nodiscard]] QList<quint16> column(int index) const
    {
        QList<quint16> out;
        out.reserve(samples.size());
        for (const QList<quint16> &s : samples)
            out.append(s.value(index));
        return out;
    }
};

} // namespace mbscope
