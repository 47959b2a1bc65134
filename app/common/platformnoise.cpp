#include "common/platformnoise.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QString>
#include <QtCore/qlogging.h>

#include <cstdio>

namespace mbscope::app {

namespace {

QtMessageHandler g_previous = nullptr;

void filter(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if (type != QtFatalMsg && type != QtCriticalMsg
        && PlatformNoise::isNoise(context.category, message.toUtf8().constData()))
        return;
    if (g_previous)
        g_previous(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

} // namespace

bool PlatformNoise::isNoise(const char *category, const char *text)
{
    const QByteArrayView message(text ? text : "");
    // Qt's platform plugins log under qt.qpa.* (fonts, input methods, the offscreen backing store).
    if (category && QByteArrayView(category).startsWith("qt.qpa."))
        return true;
    // qstandardpaths_unix.cpp: "QStandardPaths: XDG_RUNTIME_DIR not set, defaulting to '...'",
    // and its complaints about a runtime directory it then replaces.
    if (message.startsWith("QStandardPaths: XDG_RUNTIME_DIR") || message.startsWith("QStandardPaths: runtime directory")
        || message.startsWith("QStandardPaths: wrong permissions on runtime directory"))
        return true;
    // qplatformwindow.cpp, the offscreen plugin's windows.
    return message.startsWith("This plugin does not support");
}

void PlatformNoise::suppress()
{
    static bool installed = false;
    if (installed)
        return;
    installed = true;
    g_previous = qInstallMessageHandler(filter);
}

} // namespace mbscope::app
