#pragma once

#include <QtCore/QMap>
#include <QtCore/QString>

#include <chrono>
#include <optional>

namespace mbscope {

// What a device does beyond answering requests (docs/profiles.md, "Device limits"): the unit ids it
// does not have, how fast it can be asked, how many clients it takes, how much it reads or writes
// at once, and how long it needs after a connection opens. The defaults limit nothing.
struct DeviceLimits {
    // A request over the network to a unit id the profile does not list: Auto answers exception
    // 0B on network endpoints and stays silent on serial lines (SimEndpointOptions); FirstUnit
    // answers as the first unit, as many TCP servers do (network endpoints only; serial lines stay
    // silent); Exception answers 0B, Silent never answers.
    enum class UnknownUnit : quint8 { Auto, FirstUnit, Exception, Silent };
    // A request closer than minGapMs to the previous one the device took: exception 06 (server
    // device busy, V1.1b3 section 7) or no answer.
    enum class TooSoon : quint8 { Busy, Silent };
    // A client beyond maxClients: refused (accepted and closed at once), or the oldest client
    // knocked off to make room, as some gateways do.
    enum class ExtraClient : quint8 { Refuse, DropOldest };

    UnknownUnit unknownUnit = UnknownUnit::Auto;
    double minGapMs = 0;                    // 0: any gap
    TooSoon tooSoon = TooSoon::Busy;
    int maxClients = 0;                     // stream endpoints; 0: the endpoint's default (64)
    ExtraClient extraClients = ExtraClient::Refuse;
    QMap<quint8, int> maxQuantity;          // function code -> most registers or bits per request
    double warmUpMs = 0;                    // requests this soon after a connection opens are ignored
    // Stream endpoints (tcp, rtu-tcp, ascii-tcp, tls): the connection is closed after each answer,
    // as some cheap devices and gateways do; the client connects again for the next request.
    bool closesAfterAnswer = false;
    bool answersBroadcasts = false;         // "answersBroadcasts": serial lines answer unit 0 (a deviation)

    // The waits a client keeps for minGapMs and warmUpMs, with some to spare, in whole
    // milliseconds (0: none): the device counts its gap from a request's arrival (a client waits
    // from the end of the exchange, later still: 1 ms more) and its warm-up from when it took the
    // connection in, which can be milliseconds after the client saw it open (a tenth more, at
    // least 2 ms). poll --profile and watches made from a profile keep these.
    [[nodiscard]] std::chrono::milliseconds clientGap() const;
    [[nodiscard]] std::chrono::milliseconds clientWarmUp() const;
    [[nodiscard]] bool limitsRequests() const { return minGapMs > 0 || !maxQuantity.isEmpty() || warmUpMs > 0; }
    [[nodiscard]] static QString unknownUnitName(UnknownUnit policy); // "first", "exception", "silent", "auto"
    // A function code as a "maxQuantity" key: "0x03", "0x0F". And back: hex text ("0x03", "0X0f")
    // or decimal ("3"); nullopt for anything else.
    [[nodiscard]] static QString functionKey(int code);
    [[nodiscard]] static std::optional<int> parseFunctionKey(const QString &key);

    friend bool operator==(const DeviceLimits &, const DeviceLimits &) = default;
};

} // namespace mbscope
