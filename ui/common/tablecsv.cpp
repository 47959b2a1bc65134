#include "tablecsv.h"

#include <QtCore/QAbstractItemModel>
#include <QtCore/QCoreApplication>
#include <QtCore/QSaveFile>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

QString csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n'))
        && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

void appendRow(QString &csv, const QStringList &fields)
{
    QStringList escaped;
    escaped.reserve(fields.size());
    for (const QString &field : fields)
        escaped.append(csvField(field));
    csv += escaped.join(QLatin1Char(',')) + QLatin1String("\r\n");
}

} // namespace

QString TableCsv::toCsv(const QAbstractItemModel &model)
{
    QString csv;
    const int columns = model.columnCount();
    QStringList header;
    for (int column = 0; column < columns; ++column)
        header.append(model.headerData(column, Qt::Horizontal, Qt::DisplayRole).toString());
    appendRow(csv, header);
    for (int row = 0; row < model.rowCount(); ++row) {
        QStringList fields;
        for (int column = 0; column < columns; ++column)
            fields.append(model.data(model.index(row, column), Qt::DisplayRole).toString());
        appendRow(csv, fields);
    }
    return csv;
}

bool TableCsv::save(const QAbstractItemModel &model, const QString &path, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        *error = QCoreApplication::translate("mbscope::TableCsv", "cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(toCsv(model).toUtf8());
    if (!file.commit()) {
        *error = QCoreApplication::translate("mbscope::TableCsv", "cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace mbscope
