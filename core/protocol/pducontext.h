#pragma once

#include "fieldtree.h"
#include "framing.h"

#include <QtCore/QByteArrayView>

namespace mbscope {

// What a function's dissector gets: the tree to append to, where the PDU lies in the frame,
// the direction, and the matching request's PDU (function code first) when one is known.
struct PduContext {
    FieldTree &tree;
    int parent = -1;        // field index the PDU's fields hang under (-1: top level)
    int offset = 0;         // frame offset of the function code
    int length = 0;         // bytes of PDU present, function code included (may be short)
    Direction direction = Direction::Request;
    QByteArrayView request; // matching request PDU, or empty

    [[nodiscard]] quint8 function() const { return byte(0); }
    [[nodiscard]] bool has(int pduOffset, int bytes = 1) const { return pduOffset >= 0 && pduOffset + bytes <= length; }
    [[nodiscard]] quint8 byte(int pduOffset) const
    {
        return quint8(tree.frame().at(offset + pduOffset));
    }
    [[nodiscard]] quint16 u16(int pduOffset) const // big-endian, as every Modbus data item
    {
        return quint16((byte(pduOffset) << 8) | byte(pduOffset + 1));
    }
    [[nodiscard]] bool hasRequest() const { return !request.isEmpty(); }
    [[nodiscard]] quint8 requestByte(int pduOffset) const
    {
        return pduOffset < request.size() ? quint8(request.at(pduOffset)) : 0;
    }
    [[nodiscard]] quint16 requestU16(int pduOffset) const
    {
        return quint16((requestByte(pduOffset) << 8) | requestByte(pduOffset + 1));
    }
    // Appends a field at a PDU-relative offset.
    int add(const char *key, const char *name, int pduOffset, int bytes, quint64 value = 0,
            ValueFormat format = ValueFormat::None, const char *meaning = nullptr) const
    {
        return tree.add(parent, key, name, offset + pduOffset, bytes, value, format, meaning);
    }
    int addChild(int parentField, const char *key, const char *name, int pduOffset, int bytes,
                 quint64 value = 0, ValueFormat format = ValueFormat::None, const char *meaning = nullptr) const
    {
        return tree.add(parentField, key, name, offset + pduOffset, bytes, value, format, meaning);
    }
};

} // namespace mbscope
