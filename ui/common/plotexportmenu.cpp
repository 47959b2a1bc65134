#include "plotexportmenu.h"

#include "lastfolder.h"

#include "plotsaver.h"

#include <QtGui/QAction>
#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QMenu>
#include <qcustomplot.h>

namespace mbscope {

PlotExportMenu::PlotExportMenu(QCustomPlot *plot, const QString &baseName)
    : QObject(plot)
    , m_plot(plot)
    , m_baseName(baseName)
    , m_save(new QAction(tr("&Save plot as…"), this))
    , m_copy(new QAction(tr("&Copy plot"), this))
{
    m_save->setToolTip(tr("Save the plot as a PNG image, an SVG drawing or a PDF document"));
    m_copy->setToolTip(tr("Copy the plot to the clipboard as an image"));
    connect(m_save, &QAction::triggered, this, &PlotExportMenu::askAndSave);
    connect(m_copy, &QAction::triggered, this, &PlotExportMenu::copyToClipboard);

    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(plot, &QWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        QMenu menu(m_plot);
        menu.addAction(m_save);
        menu.addAction(m_copy);
        menu.exec(m_plot->mapToGlobal(pos));
    });
}

bool PlotExportMenu::saveTo(const QString &path, QString *error) const
{
    const QSize size = m_plot->size().isValid() && !m_plot->size().isEmpty() ? m_plot->size() : QSize(900, 500);
    return PlotSaver::save(*m_plot, path, size.width(), size.height(), error);
}

void PlotExportMenu::copyToClipboard() const
{
    QGuiApplication::clipboard()->setPixmap(m_plot->toPixmap());
}

void PlotExportMenu::askAndSave()
{
    const QString path = QFileDialog::getSaveFileName(m_plot, tr("Save plot"), LastFolder::start(m_baseName + QStringLiteral(".png")),
                                                      PlotSaver::fileFilter());
    LastFolder::remember(path);
    if (path.isEmpty())
        return;
    QString error;
    if (saveTo(path, &error))
        Q_EMIT saved(tr("Plot saved to %1").arg(path));
    else
        Q_EMIT saved(tr("Plot not saved: %1").arg(error));
}

} // namespace mbscope
