#pragma once

#include <QtCore/QString>

namespace mbscope {

// Where the window's file dialogs open: the folder of the last file (or the last folder) the user
// picked or saved in any of them, kept in QSettings ("files/lastFolder") across starts; the home
// folder before the first pick, never the working directory the window was started from.
class LastFolder
{
public:
    static constexpr const char *kSettingsKey = "files/lastFolder";

    // fileName (a suggested name, or empty) in the last folder; a fileName with a folder of its
    // own (an absolute path) is kept as it is.
    [[nodiscard]] static QString start(const QString &fileName = QString());
    // Remembers where path is: a folder itself, else the folder of the file. An empty path (a
    // cancelled dialog) changes nothing.
    static void remember(const QString &path);
    // The folder start() uses.
    [[nodiscard]] static QString folder();
};

} // namespace mbscope
