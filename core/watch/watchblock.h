#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// The data of one answer to a watch's read: registers (two per address in an Enron watch) or bits.
struct WatchAnswer {
    bool ok = false;
    quint8 exceptionCode = 0; // an exception answer (ok false, error names it)
    QString error;            // what is wrong with the answer, and where
    QList<quint16> words;     // registers in wire order; Enron: two per 32-bit value
    QList<bool> bits;         // coils and discrete inputs
};

// What goes on the wire for a watch, and what comes back, read into words or bits.
//
// The quantity limits are those of the request (MODBUS Application Protocol V1.1b3): 2000 bits
// (6.1, 6.2), 125 registers (6.3, 6.4), a FIFO of at most 31 values (6.18). An Enron/Daniel
// watch reads 32-bit registers, four bytes each: the answer's data is then 4 x quantity bytes and
// a PDU holds at most 253 bytes (4.1), function code and byte count leaving 251, so at most 62
// values (248 bytes; 63 would be 252).
class WatchBlock
{
public:
    // A point's format as the watch reads it: in an Enron watch a 16-bit format reads the whole
    // 32-bit register (u16 as u32, i16 as i32, with the format's order), other formats as given.
    [[nodiscard]] static RegisterFormat effectiveFormat(const WatchDefinition &watch, const WatchPoint &point);
    // Most addresses one read of the function may ask for (0 for a function no watch reads).
    [[nodiscard]] static int maxQuantity(quint8 function, bool enron32);
    [[nodiscard]] static bool isBitFunction(quint8 function) { return function == 1 || function == 2; }
    [[nodiscard]] static bool isWatchFunction(quint8 function)
    {
        return (function >= 1 && function <= 4) || function == 0x18;
    }
    // Registers each address of the watch holds: 2 for Enron watches, else 1 (bits: 1).
    [[nodiscard]] static int wordsPerAddress(const WatchDefinition &watch)
    {
        return watch.enron32 && !isBitFunction(watch.function) ? 2 : 1;
    }
    // The request PDU (function code first).
    [[nodiscard]] static QByteArray requestPdu(const WatchDefinition &watch);
    // The answer's PDU (function code first) read for the watch's request: an exception, or the
    // words or bits with their count checked against the quantity asked for.
    [[nodiscard]] static WatchAnswer readAnswer(const WatchDefinition &watch, QByteArrayView responsePdu);
    // The PDU that writes words to address of the watch, or empty with *error saying why: only a
    // point marked writable, of a holding-register watch (03: 06 for one register, 10 for more;
    // Enron: 10 with one 32-bit value per address) or a coil watch (01: 05 for one coil, 0F for
    // more, each word 0 or 1), and only as many words as the point holds.
    [[nodiscard]] static QByteArray writePdu(const WatchDefinition &watch, quint16 address,
                                             const QList<quint16> &words, QString *error);
};

} // namespace mbscope
