#pragma once

#include "simtable.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>
#include <optional>

namespace mbscope {

// The answer templates of delimited protocols (LineRule): text with {capture} and
// {table:first-last} fields, {{ and }} for literal braces.
class LineTemplate
{
public:
    struct Field {
        QString capture;      // a capture's name, or empty for a table field
        SimTable table = SimTable::HoldingRegisters;
        int first = 0;
        int last = 0;
    };
    // Values of a table, or nullopt when an address is missing.
    using Lookup = std::function<std::optional<QList<quint16>>(SimTable table, int first, int count)>;

    // The fields of text, or an error ("character 5: '{' is not closed").
    [[nodiscard]] static std::optional<QList<Field>> fields(const QString &text, QString *error);
    // text with its fields filled in; captures by name; nullopt with *error when a table
    // address does not exist.
    [[nodiscard]] static std::optional<QString> expand(const QString &text, const std::function<QString(const QString &)> &capture,
                                                       const Lookup &lookup, QString *error);
    // "coils" -> Coils ...; nullopt for anything else.
    [[nodiscard]] static std::optional<SimTable> tableNamed(QStringView name);
};

} // namespace mbscope
