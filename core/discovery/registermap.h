#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

namespace mbscope {

// A run of consecutive addresses that exist in one table, with the values read from them.
struct MapBlock {
    quint16 address = 0;
    QList<quint16> values; // registers, or bits as 0/1

    [[nodiscard]] int count() const { return int(values.size()); }
    [[nodiscard]] int last() const { return int(address) + count() - 1; }
};

// What a register-map scan learnt about one table (read function 01-04).
struct TableMap {
    quint8 function = 3;
    bool supported = false;  // the function was accepted (anything but exception 01 or silence)
    int maxQuantity = 0;     // the largest quantity read without exception 03; 0: not known
    QList<MapBlock> blocks;  // in address order
    int requests = 0;        // requests spent on the table
    int searchedFirst = 0;   // the addresses searched
    int searchedLast = 0;
    // 0A or 0B: a gateway answered the table's first read for the unit (no path, or nothing
    // answered behind it): no device, so nothing is known of the function. 0 otherwise.
    quint8 gatewayException = 0;
    // The first address after a block whose one-register read got exception 02 (-1: none). With a
    // block after it, the device refuses a read over the gap between (a profile's gapReads
    // "exception"), which no read may span.
    int firstGapRefusal = -1;
    [[nodiscard]] bool refusesGapReads() const
    {
        return blocks.size() >= 2 && firstGapRefusal >= 0 && firstGapRefusal < int(blocks.constLast().address);
    }
};

// Whether an optional function (or a diagnostics sub-function) is answered.
struct FunctionSupport {
    quint8 function = 0;
    int subFunction = -1;    // 08 and 2B: the sub-function or MEI type asked; -1 otherwise
    enum class Answer : quint8 { Answers, Exception, Silent, NotProbed } answer = Answer::Silent;
    quint8 exceptionCode = 0;
    QString note;            // what was asked, or why it was not

    // A device that answers 02 or 03 knows the function: only 01 (or silence) says it does not.
    // 0A and 0B come from a gateway with no device behind it: they say nothing of the function.
    [[nodiscard]] bool known() const
    {
        return answer == Answer::Answers || (answer == Answer::Exception && exceptionCode != 0x01 && !fromGateway());
    }
    [[nodiscard]] bool fromGateway() const
    {
        return answer == Answer::Exception && (exceptionCode == 0x0A || exceptionCode == 0x0B);
    }
};

// Everything a register-map scan learnt about one unit.
struct RegisterMap {
    quint8 unit = 1;
    QList<TableMap> tables;              // 01, 02, 03, 04
    QList<FunctionSupport> functions;    // the optional ones
    int exceptionStatus = -1;            // the answer to 07, -1 without one
    QByteArray serverIdData;             // the answer to 11 after its byte count, empty without one
    int requests = 0;

    [[nodiscard]] const TableMap *table(quint8 function) const
    {
        for (const TableMap &t : tables) {
            if (t.function == function)
                return &t;
        }
        return nullptr;
    }
};

} // namespace mbscope
