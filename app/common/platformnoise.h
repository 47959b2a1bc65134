#pragma once

namespace mbscope::app {

// A headless plot (poll, sweep, analyze or export with --histogram or --timeseries, and
// --screenshot) starts a QApplication on the offscreen platform only to draw a PNG. Qt then
// warns about things that concern a desktop session, not the user of a command: no
// XDG_RUNTIME_DIR (QStandardPaths, when run from cron, a container or CI) and a platform plugin
// that cannot propagate size hints (QPlatformWindow, on the offscreen plugin). A CLI's stderr
// carries only what concerns the user (issue 19), so this message handler drops those platform
// messages and passes every other message to the handler it replaces.
class PlatformNoise
{
public:
    static void suppress();
    // Whether a message is one of those (its category and text).
    [[nodiscard]] static bool isNoise(const char *category, const char *text);
};

} // namespace mbscope::app
