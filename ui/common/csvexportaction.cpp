#include "csvexportaction.h"

#include "lastfolder.h"

#include "tablecsv.h"

#include <QtWidgets/QFileDialog>
#include <QtWidgets/QWidget>

namespace mbscope {

CsvExportAction::CsvExportAction(const QAbstractItemModel *model, const QString &baseName, QWidget *parent)
    : QAction(tr("Export table as &CSV…"), parent)
    , m_model(model)
    , m_baseName(baseName)
    , m_dialogParent(parent)
{
    setToolTip(tr("Save the table as comma-separated values"));
    connect(this, &QAction::triggered, this, &CsvExportAction::askAndSave);
}

void CsvExportAction::askAndSave()
{
    const QString path = QFileDialog::getSaveFileName(m_dialogParent, tr("Export table"), LastFolder::start(m_baseName + QStringLiteral(".csv")),
                                                      tr("CSV file (*.csv)"));
    LastFolder::remember(path);
    if (path.isEmpty())
        return;
    QString error;
    if (TableCsv::save(*m_model, path, &error))
        Q_EMIT saved(tr("Table saved to %1").arg(path));
    else
        Q_EMIT saved(tr("Table not saved: %1").arg(error));
}

} // namespace mbscope
