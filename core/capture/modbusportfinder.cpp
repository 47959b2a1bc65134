#include "modbusportfinder.h"

#include "capture/decodedpacket.h"
#include "protocol/checksum.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace mbscope {

namespace {

constexpr qsizetype kMbapProbe = 8; // the MBAP header and the function code

bool plausibleFunction(quint8 code)
{
    return (code & 0x7f) != 0;
}

} // namespace

QString ModbusPortFinder::Found::description() const
{
    const QString transport = udp ? QStringLiteral("UDP") : QStringLiteral("TCP");
    return framing == Framing::Rtu ? QStringLiteral("RTU over %1 on port %2").arg(transport).arg(port)
                                   : QStringLiteral("Modbus/%1 on port %2").arg(transport).arg(port);
}

bool ModbusPortFinder::isMbapPayload(QByteArrayView payload)
{
    qsizetype at = 0;
    while (at < payload.size()) {
        const QByteArrayView frame = payload.sliced(at);
        if (frame.size() < kMbapProbe || frame[2] != 0 || frame[3] != 0 || frame[4] != 0)
            return false;
        const int length = quint8(frame[5]);
        if (length < 2 || length > 254 || !plausibleFunction(quint8(frame[7])) || frame.size() < 6 + length)
            return false;
        at += 6 + length;
    }
    return at > 0;
}

bool ModbusPortFinder::isRtuPayload(QByteArrayView payload)
{
    if (payload.size() < 4 || payload.size() > 256 || !plausibleFunction(quint8(payload[1])))
        return false;
    const quint16 crc = checksum::crc16Modbus(payload.first(payload.size() - 2));
    return quint8(payload[payload.size() - 2]) == (crc & 0xff) && quint8(payload[payload.size() - 1]) == crc >> 8;
}

void ModbusPortFinder::add(const DecodedPacket &packet)
{
    if (packet.payload.isEmpty() || packet.truncated)
        return;
    const bool udp = packet.outcome == DecodedPacket::Outcome::Udp;
    const quint16 low = std::min(packet.sourcePort, packet.destinationPort);
    const quint16 high = std::max(packet.sourcePort, packet.destinationPort);
    const quint64 key = quint64(udp) << 32 | quint64(low) << 16 | high;
    const bool mbap = isMbapPayload(packet.payload);
    const bool rtu = !mbap && isRtuPayload(packet.payload);
    auto it = m_flows.find(key);
    if (it == m_flows.end()) {
        if ((!mbap && !rtu) || m_flows.size() >= kMaxFlows)
            return;
        it = m_flows.emplace(key, Tally{}).first;
    }
    Tally &t = it->second;
    if (mbap)
        ++t.mbap;
    else if (rtu)
        ++t.rtu;
    else
        ++t.other;
}

std::vector<ModbusPortFinder::Found> ModbusPortFinder::found() const
{
    std::map<std::tuple<bool, quint16, Framing>, quint64> byPort;
    for (const auto &[key, t] : m_flows) {
        const quint64 modbus = t.mbap + t.rtu;
        if (modbus < 2 || modbus < t.other)
            continue;
        const bool udp = (key >> 32) != 0;
        const quint16 server = quint16(key >> 16);
        const Framing framing = t.mbap >= t.rtu ? (udp ? Framing::Udp : Framing::Tcp) : Framing::Rtu;
        byPort[{udp, server, framing}] += modbus;
    }
    std::vector<Found> list;
    for (const auto &[where, packets] : byPort)
        list.push_back({std::get<0>(where), std::get<1>(where), std::get<2>(where), packets});
    std::stable_sort(list.begin(), list.end(), [](const Found &a, const Found &b) { return a.packets > b.packets; });
    return list;
}

} // namespace mbscope
