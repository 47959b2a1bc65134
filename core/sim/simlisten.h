#pragma once

#include <QtCore/QString>
#include <QtNetwork/QHostAddress>

#include <optional>

namespace mbscope {

// The address a network endpoint binds: an IP address as written in the URL, or "localhost"
// (127.0.0.1). Host names other than localhost are refused, so that a server never listens on
// an interface the user did not name. *error says why.
[[nodiscard]] std::optional<QHostAddress> listenAddress(const QString &host, QString *error);

} // namespace mbscope
