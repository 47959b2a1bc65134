#pragma once
// Helpers shared by the window's GUI tests: isolated settings and screenshots in the output dir.

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtCore/QStandardPaths>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>
#include <QtTest/QTest>

namespace mbscope::guitest {

// QSettings of a test never touch the user's, nor another test program's: each test program
// starts with empty settings in a folder of its own, removed when it ends. (They shared one file,
// so what one program left, a fault rule of the built-in simulator, reached the others, in
// whatever order CTest ran them.)
inline void isolateSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    static QTemporaryDir folder;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder.path());
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
