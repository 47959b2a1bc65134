#pragma once

#include <QtGui/QAction>

class QAbstractItemModel;
class QWidget;

namespace mbscope {

// "Export as CSV…" for a table: asks for a file name and writes the model with TableCsv.
class CsvExportAction : public QAction
{
    Q_OBJECT

public:
    // baseName: the file name the dialog suggests, without extension ("latency-statistics").
    CsvExportAction(const QAbstractItemModel *model, const QString &baseName, QWidget *parent);

Q_SIGNALS:
    // After a save from the dialog: what was written, or why not (for the status bar).
    void saved(const QString &message);

private:
    void askAndSave();

    const QAbstractItemModel *m_model;
    QString m_baseName;
    QWidget *m_dialogParent;
};

} // namespace mbscope
