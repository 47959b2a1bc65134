#pragma once
// Helpers shared by the window's GUI tests: isolated settings and screenshots in the output dir.

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QStandardPaths>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>
#include <QtTest/QTest>

namespace mbscope::guitest {

// QSettings of a test never touch the user's: test mode paths and an organisation of their own.
inline void isolateSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("mbscope-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("mbscope-gui-tests"));
}

// Where screenshots go: $MBSCOPE_TEST_OUTPUT_DIR, else the test's working directory (CTest runs
// it in the build tree's tests/ui).
inline QString outputPath(const QString &fileName)
{
    const QString dir = qEnvironmentVariableIsSet("MBSCOPE_TEST_OUTPUT_DIR")
                            ? qEnvironmentVariable("MBSCOPE_TEST_OUTPUT_DIR")
                            : QDir::currentPath();
    return QDir(dir).filePath(fileName);
}

// Renders widget to fileName in the output dir and checks the file was written.
inline bool saveShot(QWidget *widget, const QString &fileName)
{
    QCoreApplication::sendPostedEvents();
    const QString path = outputPath(fileName);
    const bool ok = widget->grab().save(path, "PNG");
    qInfo("screenshot: %s", qPrintable(path));
    return ok;
}

} // namespace mbscope::guitest
