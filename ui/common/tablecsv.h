#pragma once

#include <QtCore/QString>

class QAbstractItemModel;

namespace mbscope {

// A table model as CSV (RFC 4180: comma separated, fields with a comma, quote or line break in
// double quotes, quotes doubled, CRLF line ends): the header row, then every row as displayed.
// What every table in the window exports ("Export as CSV…").
class TableCsv
{
public:
    [[nodiscard]] static QString toCsv(const QAbstractItemModel &model);
    // Writes atomically (QSaveFile): false with the reason in error, and the old file untouched.
    [[nodiscard]] static bool save(const QAbstractItemModel &model, const QString &path, QString *error);
};

} // namespace mbscope
