#pragma once

#include "protocol/framing.h"
#include "protocol/streamframer.h"

#include <memory>

namespace mbscope {

class LinkUrl;
struct EngineOptions;

// How the engine cuts answers out of what a link receives, from the target URL:
// - tcp, tls: MbapFramer over the stream; udp: MbapFramer fed one datagram at a time;
// - rtu-tcp, rtu-udp, rtu: RtuFramer(Direction::Response); ascii-tcp, ascii: AsciiFramer;
// - ?framing=delimited on any link: DelimitedFramer.
struct LinkFraming {
    Framing framing = Framing::Tcp; // the Modbus framing (meaningless when delimited)
    bool delimited = false;
    bool datagram = false;          // every datagram is whole: flush the framer after each
    // Quiet time after the last byte after which bytes the framer still holds are ended (RTU
    // only: t3.5 on serial lines, EngineOptions::streamSilenceMs over TCP); 0: never.
    qint64 silenceNs = 0;
    int baud = 0;                   // serial RTU: the framer waits out t3.5 (RtuFramer::onSilence)

    [[nodiscard]] static LinkFraming of(const LinkUrl &url, const EngineOptions &options);
    [[nodiscard]] std::unique_ptr<StreamFramer> createFramer(const LinkUrl &url) const;
};

} // namespace mbscope
