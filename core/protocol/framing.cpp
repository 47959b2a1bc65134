#include "framing.h"

namespace mbscope {

QString framingName(Framing framing)
{
    switch (framing) {
    case Framing::Auto: return QStringLiteral("auto");
    case Framing::Rtu: return QStringLiteral("rtu");
    case Framing::Ascii: return QStringLiteral("ascii");
    case Framing::Tcp: return QStringLiteral("tcp");
    case Framing::Udp: return QStringLiteral("udp");
    case Framing::Pdu: return QStringLiteral("pdu");
    }
    return QStringLiteral("auto");
}

QString directionName(Direction direction)
{
    switch (direction) {
    case Direction::Auto: return QStringLiteral("auto");
    case Direction::Request: return QStringLiteral("request");
    case Direction::Response: return QStringLiteral("response");
    }
    return QStringLiteral("auto");
}

std::optional<Framing> framingFromName(QStringView name)
{
    for (Framing f : {Framing::Auto, Framing::Rtu, Framing::Ascii, Framing::Tcp, Framing::Udp, Framing::Pdu}) {
        if (name.compare(framingName(f), Qt::CaseInsensitive) == 0)
            return f;
    }
    if (name.compare(u"mbap", Qt::CaseInsensitive) == 0)
        return Framing::Tcp;
    return std::nullopt;
}

std::optional<Direction> directionFromName(QStringView name)
{
    for (Direction d : {Direction::Auto, Direction::Request, Direction::Response}) {
        if (name.compare(directionName(d), Qt::CaseInsensitive) == 0)
            return d;
    }
    return std::nullopt;
}

} // namespace mbscope
