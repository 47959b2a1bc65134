// A test-only executable: `mbscope simulate` without the rest of mbscope, so the simulator's
// command can be tested while the subcommand table is edited elsewhere.
#include "simulatecommand.h"

#include <QtCore/QCoreApplication>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("mbscope"));
    // As mbscope's table hands it over: the subcommand's name first.
    QStringList arguments = QCoreApplication::arguments();
    arguments[0] = QStringLiteral("simulate");
    return mbscope::app::runSimulate(arguments);
}
