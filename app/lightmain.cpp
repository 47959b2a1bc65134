// mbscope, the light executable: the commands that talk to a device or read a file, linked
// against QtCore, QtNetwork and QtSerialPort only; everything else is handed to mbscope-full
// (launcher.h) before Qt starts. main.cpp is mbscope-full's.
#include "commands.h"
#include "launcher.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

int main(int argc, char *argv[])
{
    if (mbscope::app::Launcher::needsFull(argc, argv))
        return mbscope::app::Launcher::execFull(argv);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("mbscope"));
    QCoreApplication::setApplicationVersion(QStringLiteral(MBSCOPE_VERSION));
    return mbscope::app::runHeadless(QCoreApplication::arguments());
}
