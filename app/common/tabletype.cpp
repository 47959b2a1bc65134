#include "common/tabletype.h"

namespace mbscope::app {

TableType TableType::parse(const QString &text, bool bigEndianWords)
{
    TableType t;
    const QString typed = text.trimmed();
    const QString table = typed.section(QLatin1Char(':'), 0, 0).trimmed();
    const bool hasSuffix = typed.contains(QLatin1Char(':'));
    const QString suffix = typed.section(QLatin1Char(':'), 1).trimmed().toLower();
    if (table == QLatin1String("0"))
        t.functionCode = 0x01;
    else if (table == QLatin1String("1"))
        t.functionCode = 0x02;
    else if (table == QLatin1String("3"))
        t.functionCode = 0x04;
    else if (table == QLatin1String("4"))
        t.functionCode = 0x03;
    if (t.functionCode == 0) {
        t.error = QStringLiteral("-t/--table '%1' is not a table: expected 0 (coils), 1 (discrete inputs), 3 (input "
                                 "registers) or 4 (holding registers), the first digit of its Modicon references as in "
                                 "mbpoll's -t")
                      .arg(text);
        return t;
    }
    const bool registers = t.functionCode >= 0x03;
    if (hasSuffix && !registers) {
        t.error = QStringLiteral("-t/--table %1: coils and discrete inputs are bits, shown as 1 or 0; a display suffix "
                                 "(:hex, :int, :float) applies to tables 3 and 4")
                      .arg(text);
        return t;
    }
    const bool mbpollWide = suffix == QLatin1String("int") || suffix == QLatin1String("float");
    if (bigEndianWords && !mbpollWide) {
        t.error = QStringLiteral("-B/--big-endian orders the words of -t's :int and :float (mbpoll's -B), but -t is %1: "
                                 "give a --format with a byte order (f32, f32-cdab...) instead")
                      .arg(text);
        return t;
    }
    if (hasSuffix) {
        const QString name = suffix == QLatin1String("int")     ? (bigEndianWords ? QStringLiteral("i32") : QStringLiteral("i32-cdab"))
                             : suffix == QLatin1String("float") ? (bigEndianWords ? QStringLiteral("f32") : QStringLiteral("f32-cdab"))
                                                                : suffix;
        const RegisterFormatResult f = RegisterFormat::parse(name);
        if (!f.ok) {
            t.error = QStringLiteral("-t/--table %1: '%2' is not a display: expected hex, int or float (mbpoll's), or "
                                     "a --format name (u16, i16, u32, f32-cdab...)")
                          .arg(text, suffix);
            return t;
        }
        t.format = f.format;
    }
    t.ok = true;
    return t;
}

} // namespace mbscope::app
