#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testpackaging {

// One option as QCommandLineParser's help lists it: "  --framing <framing>   auto, rtu...".
struct HelpOption {
    QString name;      // "framing" (the long name; "h" when only a short one exists)
    QString valueName; // "framing"; empty for a flag
    QString shortName; // "a" of "-a, --unit <id>"; empty when the option has none (or no long name)
};

// The options in a subcommand's --help ("Options:" up to the next heading or the end).
[[nodiscard]] QList<HelpOption> helpOptions(const QString &help);
// The subcommands `mbscope --help` lists under "Subcommands:".
[[nodiscard]] QStringList helpSubcommands(const QString &help);

} // namespace mbscope::testpackaging
