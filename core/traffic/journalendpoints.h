#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// The endpoints note of a traffic journal (trafficjournal.h, a note record): which connection a
// link's frames went over from this note on, as the socket had it:
//   {"endpoints": {"client": "127.0.0.1:40312", "server": "127.0.0.1:1502"}}
// client: the end that sent the requests (mbscope's own socket when it polled, the peer when it
// served); server: the end that answered. IPv6 addresses in brackets ("[::1]:502"). Written by
// the engine when its TCP or UDP link opens and by the simulator when a request comes from
// another client than the last one on the endpoint (transaction id 0 from the engine, the
// request's from the simulator). Serial links have none: the link's URL names the port.
// A note is a record every journal reader of version 2 reads and skips when it does not know
// it, so journals with endpoints still open in older mbscope; journals without one are read
// with the client unknown.
struct JournalEndpoints {
    QString client;
    QString server;

    [[nodiscard]] QByteArray toJson() const;
    // The endpoints a note holds; none when the note is about something else (fault rules).
    [[nodiscard]] static std::optional<JournalEndpoints> fromJson(QByteArrayView json);

    friend bool operator==(const JournalEndpoints &, const JournalEndpoints &) = default;
};

} // namespace mbscope
