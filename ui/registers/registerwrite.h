#pragma once

#include "profile/readanswerrows.h"
#include "protocol/registerformat.h"
#include "protocol/tablewrite.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace mbscope {

// The write request an edit of a register table's cell makes: the text typed, read as a coil
// value, in a value column's format or as the profile's scaled value, into the request of the
// function the user chose. Input that cannot be written is refused with what and where
// ("register 40122 (PDU address 121), u16: '70000' is out of range for u16 (0 to 65535)"). The
// caller has checked that the table is writable and the row holds a whole value.
class RegisterWrite
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::RegisterWrite)

public:
    // A coil's row: 1/0, on/off, true/false.
    [[nodiscard]] static TableWriteResult coil(const ReadAnswerRows &rows, int row, const QString &text,
                                               WriteChoice choice);
    // A value column's cell: text in format, from the row's register.
    [[nodiscard]] static TableWriteResult value(const ReadAnswerRows &rows, int row, RegisterFormat format,
                                                const QString &text, WriteChoice choice);
    // The scaled column's cell: text as the profile's entry at row means it, its unit optional.
    [[nodiscard]] static TableWriteResult scaled(const ReadAnswerRows &rows, int row, const QString &text,
                                                 WriteChoice choice);
    // "register 40122 (PDU address 121)", "coil 1 (PDU address 0)": where a message points.
    [[nodiscard]] static QString where(const ReadAnswerRows &rows, int row);
};

} // namespace mbscope
