#pragma once

#include <QtCore/QString>
#include <QtNetwork/QHostAddress>

#include <optional>

namespace mbscope::app {

// Where a server of the watch service listens (--metrics HOST:PORT): "9464" and "localhost:9464"
// are the loopback interface, "0.0.0.0:9464" or "*:9464" every interface, "[::1]:9464" IPv6.
// Port 0: any free port (the service prints the one it got). A host is an address, "localhost" or
// "*": never a name looked up, so what a unit file says is what is exposed.
struct ListenAddress {
    QHostAddress address;
    quint16 port = 0;

    // The address as a URL's host part: "127.0.0.1", "[::1]".
    [[nodiscard]] QString hostText() const;
    [[nodiscard]] static std::optional<ListenAddress> parse(const QString &text, QString *error);
};

} // namespace mbscope::app
