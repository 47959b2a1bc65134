#include "conformance/conformancepdf.h"

#include "conformance/conformancehtml.h"

#include <QtCore/QSaveFile>
#include <QtGui/QGuiApplication>
#include <QtGui/QPageLayout>
#include <QtGui/QPageSize>
#include <QtGui/QPdfWriter>
#include <QtGui/QTextDocument>

namespace mbscope {

bool ConformancePdf::write(const ConformanceResult &result, const QString &path, QString *error)
{
    const auto fail = [error, &path](const QString &why) {
        if (error)
            *error = QStringLiteral("cannot write %1: %2").arg(path, why);
        return false;
    };
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return fail(QStringLiteral("a PDF needs the GUI's fonts (a QGuiApplication)"));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(file.errorString());
    {
        QPdfWriter pdf(&file);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        pdf.setResolution(300);
        pdf.setTitle(QStringLiteral("mbscope conform: %1, unit %2").arg(result.target).arg(result.unit));
        pdf.setCreator(QStringLiteral("mbscope conform"));
        QTextDocument document;
        document.setHtml(QString::fromUtf8(ConformanceHtml::toHtml(result)));
        document.print(&pdf); // pages as the writer's page size and margins give them
    }
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

} // namespace mbscope
