// SimProcessor: Encapsulated Interface Transport (2B) with Read Device Identification (0E),
// V1.1b3 6.19 and 6.21.
#include "sim/simbytes.h"
#include "protocol/hexnumber.h"
#include "sim/simprocessor.h"
#include "sim/simunit.h"

namespace mbscope {

namespace {

constexpr quint8 kMeiDeviceId = 0x0E;
constexpr int kMaxPdu = 253;
constexpr int kHeader = 7;                         // 2B 0E code conformity more next count
constexpr int kMaxObjectValue = kMaxPdu - kHeader - 2; // one object alone must fit a response

// The last object id of each stream access category (6.21): basic 00-02, regular 00-7F,
// extended 00-FF.
int lastObjectOf(quint8 readDeviceIdCode)
{
    switch (readDeviceIdCode) {
    case 1: return 0x02;
    case 2: return 0x7F;
    default: return 0xFF;
    }
}

} // namespace

SimReply SimProcessor::encapsulated(QByteArrayView pdu)
{
    // 6.19 state diagram: function code and MEI type supported (01), then the data (03).
    if (pdu.size() < 2)
        return SimReply::exception(0x2B, 0x03, QStringLiteral("2B needs an MEI type"));
    const quint8 mei = quint8(pdu[1]);
    if (mei != kMeiDeviceId) {
        return SimReply::exception(0x2B, 0x01, QStringLiteral("MEI type 0x%1 is not supported (only 0E, Read Device Identification)")
                                                   .arg(hexNumber(mei, 2)));
    }
    return deviceIdentification(pdu);
}

SimReply SimProcessor::deviceIdentification(QByteArrayView pdu)
{
    if (pdu.size() != 4)
        return SimReply::exception(0x2B, 0x03, QStringLiteral("2B/0E takes a Read Device ID code and an object id, %1 data bytes given").arg(pdu.size() - 2));
    const quint8 code = quint8(pdu[2]);
    quint8 objectId = quint8(pdu[3]);
    const quint8 conformity = m_unit->conformityLevel();
    // 6.21 state diagram: Read Device ID code (03), then object id (02).
    if (code < 1 || code > 4)
        return SimReply::exception(0x2B, 0x03, QStringLiteral("Read Device ID code %1 is not 1-4").arg(code));
    if (code == 4 && !(conformity & 0x80))
        return SimReply::exception(0x2B, 0x03, QStringLiteral("individual access (code 4) is not supported: conformity level 0x%1").arg(hexNumber(conformity, 2)));
    const QMap<quint8, QByteArray> objects = m_unit->deviceIdObjects();

    QByteArray bytes(kHeader, 0);
    bytes[0] = char(0x2B);
    bytes[1] = char(kMeiDeviceId);
    bytes[2] = char(code);
    bytes[3] = char(conformity);
    if (code == 4) {
        if (!objects.contains(objectId))
            return SimReply::exception(0x2B, 0x02, QStringLiteral("object id 0x%1 does not exist").arg(hexNumber(objectId, 2)));
        const QByteArray value = objects.value(objectId).left(kMaxObjectValue);
        bytes[6] = 1;
        bytes.append(char(objectId));
        bytes.append(char(value.size()));
        bytes.append(value);
        return SimReply::normal(bytes);
    }
    const int last = lastObjectOf(code);
    // "If the Object Id does not match any known object, the server responds as if object 0
    // were pointed out (restart at the beginning)."
    if (!objects.contains(objectId) || objectId > last)
        objectId = 0;
    int count = 0;
    for (auto it = objects.lowerBound(objectId); it != objects.cend() && it.key() <= last; ++it) {
        const QByteArray value = it.value().left(kMaxObjectValue);
        if (bytes.size() + 2 + value.size() > kMaxPdu) {
            bytes[4] = char(0xFF); // more follows
            bytes[5] = char(it.key()); // the next object to ask for
            break;
        }
        bytes.append(char(it.key()));
        bytes.append(char(value.size()));
        bytes.append(value);
        ++count;
    }
    if (count == 0)
        return SimReply::exception(0x2B, 0x02, QStringLiteral("no device identification objects for Read Device ID code %1").arg(code));
    bytes[6] = char(count);
    return SimReply::normal(bytes);
}

} // namespace mbscope
