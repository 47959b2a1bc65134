#include "linkframing.h"

#include "engineoptions.h"

#include "protocol/asciiframer.h"
#include "protocol/delimitedframer.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"
#include "transport/linkurl.h"

namespace mbscope {

LinkFraming LinkFraming::of(const LinkUrl &url, const EngineOptions &options)
{
    LinkFraming f;
    f.framing = url.framing();
    f.delimited = url.delimited.enabled;
    f.datagram = url.isDatagram();
    if (!f.delimited && f.framing == Framing::Rtu && !f.datagram) {
        if (url.isSerial()) {
            f.baud = url.serial.baud;
            f.silenceNs = RtuFramer::t35Ns(url.serial.baud);
        } else {
            f.silenceNs = qint64(options.streamSilenceMs) * 1000000;
        }
    }
    return f;
}

std::unique_ptr<StreamFramer> LinkFraming::createFramer(const LinkUrl &url) const
{
    if (delimited)
        return std::make_unique<DelimitedFramer>(url.delimited);
    switch (framing) {
    case Framing::Rtu: {
        auto rtu = std::make_unique<RtuFramer>(Direction::Response);
        rtu->setBaudRate(baud);
        return rtu;
    }
    case Framing::Ascii:
        return std::make_unique<AsciiFramer>();
    case Framing::Tcp:
    case Framing::Udp:
    case Framing::Pdu:
    case Framing::Auto:
        break;
    }
    return std::make_unique<MbapFramer>();
}

} // namespace mbscope
