#pragma once

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// The server ports a capture's Modbus travels on, as a user types them: "502", "502,1502",
// "502, 4001". Shared by the CLI's --port/--rtu-port and the window's capture settings.
class CapturePorts
{
public:
    // Every comma-separated item a port 1..65535 (duplicates kept once); false with *error
    // naming the item at fault: "'70000' is not a port: expected a number from 1 to 65535".
    [[nodiscard]] static bool parse(const QString &text, QList<quint16> *ports, QString *error);
    // "502, 1502"
    [[nodiscard]] static QString format(const QList<quint16> &ports);
};

} // namespace mbscope
