// The window: what `mbscope` runs without a subcommand.
#include "commands.h"

#include "decodepanel.h"
#include "mainwindow.h"

#include <QtCore/QTimer>
#include <QtGui/QPixmap>
#include <QtWidgets/QApplication>

#include <cstdio>

namespace mbscope::app {

namespace {

// The RosRao detector's register read (unit 1, 22 holding registers from 121), a frame users of
// this tool type by hand: a first run shows a real dissection instead of an empty panel.
const char kExampleFrame[] = "01 03 00 79 00 16 15 DD";

// Renders the window once it is shown and laid out, then quits: docs and GUI smoke tests use it
// with QT_QPA_PLATFORM=offscreen, so no display is needed.
void scheduleScreenshot(QApplication &app, QWidget &window, const QString &path)
{
    QTimer::singleShot(0, &window, [&app, &window, path] {
        // Layout requests are posted events; deliver them so the grab shows final geometry.
        QCoreApplication::sendPostedEvents();
        const QPixmap shot = window.grab();
        if (shot.isNull() || !shot.save(path, "PNG")) {
            std::fprintf(stderr, "mbscope: cannot write the screenshot to %s\n", qPrintable(path));
            app.exit(ExitFailure);
            return;
        }
        app.exit(ExitOk);
    });
}

} // namespace

int runGui(QApplication &app)
{
    MainWindow window;
    window.decodePanel()->setFrameText(QString::fromLatin1(kExampleFrame));
    window.decodePanel()->decodeNow();
    window.show();

    const QString screenshot = qEnvironmentVariable("MBSCOPE_SCREENSHOT");
    if (!screenshot.isEmpty())
        scheduleScreenshot(app, window, screenshot);

    bool ok = false;
    const int quitAfterMs = qEnvironmentVariableIntValue("MBSCOPE_QUIT_AFTER_MS", &ok);
    if (ok && quitAfterMs >= 0)
        QTimer::singleShot(quitAfterMs, &app, &QCoreApplication::quit);

    return app.exec();
}

} // namespace mbscope::app
