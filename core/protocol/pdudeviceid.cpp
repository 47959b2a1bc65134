// Function 2B (43) Encapsulated Interface Transport (MODBUS Application Protocol Specification
// V1.1b3, 6.19-6.21 and Annex B). MEI type 0x0E Read Device Identification is decoded object by
// object; 0x0D CANopen General Reference is shown raw (its content belongs to CiA DS-309);
// other MEI types are reserved and shown raw.
//
// Keys:
//   modbus.mei_type             Hex, meaning the MEI type's name
//   modbus.read_device_id_code  0E: 01 basic, 02 regular, 03 extended stream, 04 one object (Hex)
//   modbus.object_id            0E request: the first (stream) or only (04) object asked for (Hex)
//   modbus.conformity_level     0E response (Hex)
//   modbus.more_follows         0E response: 0x00 no, 0xFF yes (Hex)
//   modbus.next_object_id       0E response (Hex)
//   modbus.object_count         0E response: number of objects (Decimal)
//   modbus.object               0E response: one group per object, address = 0-based index,
//                               children modbus.object_id (meaning the object's name),
//                               modbus.object_length (Decimal), modbus.object_value (Ascii)
//   modbus.data                 0D and reserved MEI types: the bytes after the MEI type
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {
namespace {

using namespace checks;

const char *readDeviceIdCodeName(quint8 code)
{
    switch (code) {
    case 0x01: return QT_TRANSLATE_NOOP("mbscope::Field", "Basic device identification (stream access)");
    case 0x02: return QT_TRANSLATE_NOOP("mbscope::Field", "Regular device identification (stream access)");
    case 0x03: return QT_TRANSLATE_NOOP("mbscope::Field", "Extended device identification (stream access)");
    case 0x04: return QT_TRANSLATE_NOOP("mbscope::Field", "One specific identification object (individual access)");
    default: return QT_TRANSLATE_NOOP("mbscope::Field", "Undefined read device ID code");
    }
}

// V1.1b3, 6.21, table of objects.
const char *objectName(quint8 id)
{
    switch (id) {
    case 0x00: return QT_TRANSLATE_NOOP("mbscope::Field", "VendorName");
    case 0x01: return QT_TRANSLATE_NOOP("mbscope::Field", "ProductCode");
    case 0x02: return QT_TRANSLATE_NOOP("mbscope::Field", "MajorMinorRevision");
    case 0x03: return QT_TRANSLATE_NOOP("mbscope::Field", "VendorUrl");
    case 0x04: return QT_TRANSLATE_NOOP("mbscope::Field", "ProductName");
    case 0x05: return QT_TRANSLATE_NOOP("mbscope::Field", "ModelName");
    case 0x06: return QT_TRANSLATE_NOOP("mbscope::Field", "UserApplicationName");
    default: return id < 0x80 ? QT_TRANSLATE_NOOP("mbscope::Field", "Reserved object") : QT_TRANSLATE_NOOP("mbscope::Field", "Private object (extended, device dependent)");
    }
}

const char *conformityName(quint8 level)
{
    switch (level) {
    case 0x01: return QT_TRANSLATE_NOOP("mbscope::Field", "Basic identification (stream access only)");
    case 0x02: return QT_TRANSLATE_NOOP("mbscope::Field", "Regular identification (stream access only)");
    case 0x03: return QT_TRANSLATE_NOOP("mbscope::Field", "Extended identification (stream access only)");
    case 0x81: return QT_TRANSLATE_NOOP("mbscope::Field", "Basic identification (stream access and individual access)");
    case 0x82: return QT_TRANSLATE_NOOP("mbscope::Field", "Regular identification (stream access and individual access)");
    case 0x83: return QT_TRANSLATE_NOOP("mbscope::Field", "Extended identification (stream access and individual access)");
    default: return QT_TRANSLATE_NOOP("mbscope::Field", "Undefined conformity level");
    }
}

[[nodiscard]] bool isReservedObject(quint8 id)
{
    return id >= 0x07 && id <= 0x7F;
}

// The read device ID code field c, when present.
void checkReadDeviceIdCode(const PduContext &ctx, int c)
{
    if (c < 0)
        return;
    const quint8 code = ctx.byte(2);
    ctx.tree.setMeaning(c, readDeviceIdCodeName(code));
    if (code < 0x01 || code > 0x04) {
        ctx.tree.flag(c, Severity::Error,
                      QStringLiteral("%1 is not a read device ID code: 01 basic, 02 regular, 03 extended stream, "
                                     "04 one specific object (V1.1b3 6.21)").arg(hexByte(code)));
    }
}

void dissectDeviceIdRequest(const PduContext &ctx)
{
    static const Slot layout[] = {
        {"modbus.read_device_id_code", QT_TRANSLATE_NOOP("mbscope::Field", "Read device ID code"), 1, ValueFormat::Hex, "read device ID code and object ID"},
        {"modbus.object_id", QT_TRANSLATE_NOOP("mbscope::Field", "Object ID"), 1, ValueFormat::Hex, "object ID"},
    };
    int f[2] = {-1, -1};
    const bool whole = addFixed(ctx, ctx.parent, 2, layout, 2, f, 4, false);
    checkReadDeviceIdCode(ctx, f[0]);
    if (!whole)
        return;
    const quint8 code = ctx.byte(2);
    const quint8 id = ctx.byte(3);
    const int o = f[1];
    ctx.tree.setMeaning(o, objectName(id));
    if (isReservedObject(id)) {
        ctx.tree.flag(o, Severity::Warning,
                      QStringLiteral("%1 is a reserved object ID (0x07-0x7F)").arg(hexByte(id)));
    } else if ((code == 0x01 && id > 0x02) || (code == 0x02 && id > 0x06)) {
        // V1.1b3 6.21: a stream access from an object the category does not hold restarts at 0.
        ctx.tree.flag(o, Severity::Info,
                      QStringLiteral("%1 is outside the %2 category: the device answers from object 0x00")
                          .arg(hexByte(id), code == 0x01 ? QStringLiteral("basic (0x00-0x02)")
                                                         : QStringLiteral("regular (0x00-0x06)")));
    }
    trailing(ctx, 4);
}

// The object list of a response, from pduOffset 7 to the end of the PDU: every object present
// is shown, and the count, the order and the lengths are checked. Returns the last object's ID,
// or -1 when there is none.
int dissectObjects(const PduContext &ctx, int countField, quint8 code)
{
    const int announced = ctx.byte(6);
    int index = 0;
    int previous = -1;
    int at = 7;
    while (at < ctx.length) {
        const quint8 id = ctx.byte(at);
        const bool hasLength = ctx.has(at + 1);
        const int length = hasLength ? ctx.byte(at + 1) : 0;
        const int available = qMax(0, ctx.length - (at + 2));
        const int shown = qMin(length, available);
        const int g = ctx.add("modbus.object", QT_TRANSLATE_NOOP("mbscope::Field", "Object"), at, hasLength ? 2 + shown : 1, 0, ValueFormat::None,
                              objectName(id));
        ctx.tree.setAddress(g, index);
        const int idField = ctx.addChild(g, "modbus.object_id", QT_TRANSLATE_NOOP("mbscope::Field", "Object ID"), at, 1, id, ValueFormat::Hex, objectName(id));
        if (isReservedObject(id)) {
            ctx.tree.flag(idField, Severity::Warning,
                          QStringLiteral("%1 is a reserved object ID (0x07-0x7F)").arg(hexByte(id)));
        }
        if (previous >= 0 && id <= previous) {
            ctx.tree.flag(idField, Severity::Warning,
                          QStringLiteral("objects out of order: %1 follows %2, a stream lists objects by increasing ID")
                              .arg(hexByte(id), hexByte(quint8(previous))));
        }
        previous = id;
        ++index;
        if (!hasLength) {
            missing(ctx, g, at + 1, at + 2, true, "object length and object value");
            break;
        }
        ctx.addChild(g, "modbus.object_length", QT_TRANSLATE_NOOP("mbscope::Field", "Object length"), at + 1, 1, quint64(length), ValueFormat::Decimal);
        if (shown > 0 || length == 0)
            ctx.addChild(g, "modbus.object_value", QT_TRANSLATE_NOOP("mbscope::Field", "Object value"), at + 2, shown, 0, ValueFormat::Ascii);
        if (length > available)
            missingData(ctx, g, at + 2 + shown, at + 2, at + 2 + length, "object length");
        at += 2 + length;
    }
    if (index != announced) {
        ctx.tree.flag(countField, Severity::Error,
                      QStringLiteral("number of objects %1 but %2 present").arg(announced).arg(index));
    }
    if (code == 0x04 && index > 1) {
        ctx.tree.flag(countField, Severity::Error,
                      QStringLiteral("individual access (code 04) returns one object, %1 are present").arg(index));
    }
    return previous;
}

void dissectDeviceIdResponse(const PduContext &ctx)
{
    static const Slot layout[] = {
        {"modbus.read_device_id_code", QT_TRANSLATE_NOOP("mbscope::Field", "Read device ID code"), 1, ValueFormat::Hex,
         "read device ID code, conformity level, more follows, next object ID, number of objects and objects"},
        {"modbus.conformity_level", QT_TRANSLATE_NOOP("mbscope::Field", "Conformity level"), 1, ValueFormat::Hex,
         "conformity level, more follows, next object ID, number of objects and objects"},
        {"modbus.more_follows", QT_TRANSLATE_NOOP("mbscope::Field", "More follows"), 1, ValueFormat::Hex, "more follows, next object ID, number of objects and objects"},
        {"modbus.next_object_id", QT_TRANSLATE_NOOP("mbscope::Field", "Next object ID"), 1, ValueFormat::Hex, "next object ID, number of objects and objects"},
        {"modbus.object_count", QT_TRANSLATE_NOOP("mbscope::Field", "Number of objects"), 1, ValueFormat::Decimal, "number of objects and objects"},
    };
    int f[5] = {-1, -1, -1, -1, -1};
    const bool whole = addFixed(ctx, ctx.parent, 2, layout, 5, f, 7, true);
    const int c = f[0];
    checkReadDeviceIdCode(ctx, c);
    if (c < 0)
        return;
    const quint8 code = ctx.byte(2);
    const bool requested = ctx.request.size() >= 4 && ctx.requestByte(0) == 0x2B && ctx.requestByte(1) == 0x0E;
    if (requested && ctx.requestByte(2) != code) {
        ctx.tree.flag(c, Severity::Error,
                      QStringLiteral("does not match the request: the request's read device ID code is %1")
                          .arg(hexByte(ctx.requestByte(2))));
    }
    const int cl = f[1];
    if (cl < 0)
        return;
    const quint8 level = ctx.byte(3);
    ctx.tree.setMeaning(cl, conformityName(level));
    if ((level & 0x7F) < 0x01 || (level & 0x7F) > 0x03) {
        ctx.tree.flag(cl, Severity::Error,
                      QStringLiteral("%1 is not a conformity level: 01-03 (stream access only) or 81-83 "
                                     "(stream and individual access)").arg(hexByte(level)));
    } else if (code == 0x04 && level < 0x80) {
        ctx.tree.flag(cl, Severity::Warning,
                      QStringLiteral("the device answered an individual access (code 04) but its conformity level "
                                     "%1 says it supports stream access only").arg(hexByte(level)));
    }
    const int mf = f[2];
    if (mf < 0)
        return;
    const quint8 more = ctx.byte(4);
    if (more == 0x00) {
        ctx.tree.setMeaning(mf, QT_TRANSLATE_NOOP("mbscope::Field", "No more objects"));
    } else if (more == 0xFF) {
        ctx.tree.setMeaning(mf, QT_TRANSLATE_NOOP("mbscope::Field", "More objects follow: ask again from the next object ID"));
        if (code == 0x04) {
            ctx.tree.flag(mf, Severity::Error,
                          QStringLiteral("individual access (code 04) sets more follows to 0x00 (V1.1b3 6.21)"));
        }
    } else {
        ctx.tree.flag(mf, Severity::Error,
                      QStringLiteral("%1 is not allowed: more follows is 0x00 (no) or 0xFF (yes)").arg(hexByte(more)));
    }
    const int next = f[3];
    if (next < 0)
        return;
    if (more == 0xFF)
        ctx.tree.setMeaning(next, objectName(ctx.byte(5)));
    else if (more == 0x00 && ctx.byte(5) != 0x00) {
        ctx.tree.flag(next, Severity::Error,
                      QStringLiteral("%1 is not allowed: the next object ID is 0x00 when more follows is 0x00")
                          .arg(hexByte(ctx.byte(5))));
    }
    const int count = f[4];
    if (!whole)
        return;
    if (ctx.length <= 7) {
        // Each object takes at least its ID and length bytes.
        if (ctx.byte(6) != 0)
            missing(ctx, ctx.parent, 7, 7 + 2 * ctx.byte(6), true, "objects");
        return;
    }
    const int last = dissectObjects(ctx, count, code);
    if (requested && ctx.byte(7) != ctx.requestByte(3)) {
        // The first object's ID field comes right after the first object group.
        const int firstId = ctx.tree.indexOf("modbus.object_id", count + 1);
        if (code == 0x04 && firstId >= 0) {
            ctx.tree.flag(firstId, Severity::Error,
                          QStringLiteral("does not match the request: object %1 was asked for")
                              .arg(hexByte(ctx.requestByte(3))));
        } else if (code != 0x04 && firstId >= 0 && ctx.byte(7) != 0x00) {
            // V1.1b3 6.21: a stream starts at the object asked for, or at 0x00 when that one is unknown.
            ctx.tree.flag(firstId, Severity::Warning,
                          QStringLiteral("the stream starts at %1: the request asked from object %2 "
                                         "(or 0x00 when that one is unknown)")
                              .arg(hexByte(ctx.byte(7)), hexByte(ctx.requestByte(3))));
        }
    }
    if (more == 0xFF && last >= 0 && ctx.byte(5) <= last) {
        ctx.tree.flag(next, Severity::Warning,
                      QStringLiteral("next object ID %1 does not lie beyond the last object returned (%2): "
                                     "the next request would repeat objects")
                          .arg(hexByte(ctx.byte(5)), hexByte(quint8(last))));
    }
}

} // namespace

void dissectEncapsulatedInterface(const PduContext &ctx)
{
    static const Slot layout[] = {{"modbus.mei_type", QT_TRANSLATE_NOOP("mbscope::Field", "MEI type"), 1, ValueFormat::Hex, "MEI type"}};
    int m = -1;
    if (!addFixed(ctx, ctx.parent, 1, layout, 1, &m, 2, true))
        return;
    const quint8 mei = ctx.byte(1);
    if (isResponse(ctx) && ctx.request.size() >= 2 && ctx.requestByte(0) == 0x2B && ctx.requestByte(1) != mei) {
        ctx.tree.flag(m, Severity::Error,
                      QStringLiteral("does not match the request: the request's MEI type is %1")
                          .arg(hexByte(ctx.requestByte(1))));
    }
    if (mei == 0x0E) {
        ctx.tree.setMeaning(m, QT_TRANSLATE_NOOP("mbscope::Field", "Read Device Identification"));
        if (isResponse(ctx))
            dissectDeviceIdResponse(ctx);
        else
            dissectDeviceIdRequest(ctx);
        return;
    }
    if (mei == 0x0D) {
        ctx.tree.setMeaning(m, QT_TRANSLATE_NOOP("mbscope::Field", "CANopen General Reference"));
        ctx.tree.flag(m, Severity::Info,
                      QStringLiteral("CANopen General Reference: its data follows CiA DS-309 and is shown raw"));
    } else {
        ctx.tree.setMeaning(m, QT_TRANSLATE_NOOP("mbscope::Field", "Reserved MEI type"));
        ctx.tree.flag(m, Severity::Warning,
                      QStringLiteral("reserved MEI type %1: V1.1b3 defines 0x0D (CANopen) and 0x0E (device "
                                     "identification); the data is shown raw").arg(hexByte(mei)));
    }
    rawData(ctx, 2);
}

} // namespace mbscope::pdu
