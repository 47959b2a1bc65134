#pragma once

// mbscope's dissection translated into the names and shapes of tshark's Modbus fields, so
// tst_tshark can compare the two value by value. Numbers are decimal text, bytes lower-case hex
// without separators, as `tshark -T fields` prints them. Where tshark groups or shows things
// differently, the translation says why (see also the list at the top of tst_tshark.cpp).

#include "protocol/dissection.h"

#include <QtCore/QMap>
#include <QtCore/QSet>
#include <QtCore/QStringList>

namespace mbscope::interop {

using FieldValues = QMap<QString, QStringList>; // tshark field name -> values in frame order

struct Expected {
    FieldValues values;
    QSet<QString> prefixKeys; // tshark's value must start with ours (a tshark limitation)
};

inline QStringList values(const FieldTree &t, const char *key)
{
    QStringList list;
    for (int i : t.indexesOf(key))
        list << QString::number(t.at(i).value);
    return list;
}

inline QStringList addresses(const FieldTree &t, const char *key)
{
    QStringList list;
    for (int i : t.indexesOf(key))
        list << QString::number(t.at(i).address);
    return list;
}

inline QString raw(const FieldTree &t, const char *key)
{
    QByteArray bytes;
    for (int i : t.indexesOf(key))
        bytes += t.raw(i);
    return QString::fromLatin1(bytes.toHex());
}

inline quint64 first(const FieldTree &t, const char *key)
{
    const int i = t.indexOf(key);
    return i >= 0 ? t.at(i).value : 0;
}

inline void put(FieldValues &v, const char *tsharkKey, const QStringList &list)
{
    if (!list.isEmpty())
        v.insert(QString::fromLatin1(tsharkKey), list);
}

inline void put(FieldValues &v, const char *tsharkKey, const QString &value)
{
    if (!value.isEmpty())
        v[QString::fromLatin1(tsharkKey)] << value;
}

// Coils packed into bytes as on the wire (bit 0 of the first byte is the first coil).
inline QString packedBits(const FieldTree &t, const char *key)
{
    const QList<int> bits = t.indexesOf(key);
    QByteArray bytes((bits.size() + 7) / 8, '\0');
    for (int i = 0; i < bits.size(); ++i) {
        if (t.at(bits[i]).value)
            bytes[i / 8] = char(quint8(bytes[i / 8]) | (1 << (i % 8)));
    }
    return QString::fromLatin1(bytes.toHex());
}

// 14/15: the registers of each sub-request or sub-response, as bytes, one entry per group.
inline QStringList groupRegisters(const FieldTree &t, const char *groupKey)
{
    QStringList list;
    for (int g : t.indexesOf(groupKey)) {
        QByteArray bytes;
        for (int c : t.children(g)) {
            if (qstrcmp(t.at(c).key, "modbus.register_value") == 0)
                bytes += t.raw(c);
        }
        if (!bytes.isEmpty())
            list << QString::fromLatin1(bytes.toHex());
    }
    return list;
}

inline void translateDiagnostics(const FieldTree &t, bool response, FieldValues &v)
{
    const quint64 sub = first(t, "modbus.subfunction");
    put(v, "modbus.diagnostic_code", values(t, "modbus.subfunction"));
    put(v, response ? "modbus.diagnostic.return_query_data.echo" : "modbus.diagnostic.return_query_data.request",
        raw(t, "modbus.echo_data"));
    put(v, "modbus.diagnostic.restart_communication_option", values(t, "modbus.restart_option"));
    put(v, "modbus.diagnostic.return_diag_register", values(t, "modbus.diagnostic_register"));
    put(v, "modbus.diagnostic.ascii_input_delimiter", values(t, "modbus.ascii_delimiter"));
    static const char *const counters[] = {
        "modbus.diagnostic.bus_message_count", "modbus.diagnostic.bus_comm_error_count",
        "modbus.diagnostic.bus_exception_error_count", "modbus.diagnostic.slave_message_count",
        "modbus.diagnostic.no_slave_response_count", "modbus.diagnostic.slave_nak_count",
        "modbus.diagnostic.slave_busy_count", "modbus.diagnostic.bus_char_overrun_count"};
    if (sub >= 0x0B && sub <= 0x12)
        put(v, counters[sub - 0x0B], values(t, "modbus.counter_value"));
    if (response && sub == 0x0A)
        put(v, "modbus.diagnostic.clear_ctr_diag_reg", values(t, "modbus.diagnostic_data"));
    else
        put(v, "modbus.data", raw(t, "modbus.diagnostic_data"));
}

inline void translateFileRecords(const FieldTree &t, quint64 code, bool response, Expected &e)
{
    FieldValues &v = e.values;
    put(v, "modbus.reference_type", values(t, "modbus.reference_type"));
    QStringList counts = values(t, "modbus.byte_count");
    if (code == 0x14 && response) {
        counts += values(t, "modbus.subresponse_length");
        put(v, "modbus.data", groupRegisters(t, "modbus.file_subresponse"));
        e.prefixKeys.insert(QStringLiteral("modbus.data"));
    } else {
        // tshark shows file and record number as one 32-bit reference: file << 16 | record.
        const QStringList files = values(t, "modbus.file_number");
        const QStringList records = values(t, "modbus.record_number");
        QStringList references;
        for (int i = 0; i < qMin(files.size(), records.size()); ++i)
            references << QString::number((files[i].toULongLong() << 16) | records[i].toULongLong());
        put(v, "modbus.reference_num_32", references);
        put(v, "modbus.word_cnt", values(t, "modbus.record_length"));
        put(v, "modbus.data", groupRegisters(t, response ? "modbus.file_subresponse" : "modbus.file_subrequest"));
    }
    put(v, "modbus.byte_cnt", counts);
}

inline void translateDeviceId(const FieldTree &t, FieldValues &v)
{
    put(v, "modbus.mei", values(t, "modbus.mei_type"));
    if (first(t, "modbus.mei_type") != 0x0E) {
        put(v, "modbus.data", raw(t, "modbus.mei_type") + raw(t, "modbus.data")); // tshark counts the MEI type in
        return;
    }
    put(v, "modbus.read_device_id", values(t, "modbus.read_device_id_code"));
    put(v, "modbus.object_id", values(t, "modbus.object_id"));
    put(v, "modbus.conformity_level", values(t, "modbus.conformity_level"));
    put(v, "modbus.more_follows", values(t, "modbus.more_follows"));
    put(v, "modbus.next_object_id", values(t, "modbus.next_object_id"));
    put(v, "modbus.num_objects", values(t, "modbus.object_count"));
    put(v, "modbus.objects_len", values(t, "modbus.object_length"));
    QStringList texts;
    for (int i : t.indexesOf("modbus.object_value"))
        texts << QString::fromLatin1(t.raw(i));
    put(v, "modbus.object_str_value", texts);
}

inline Expected translate(const Dissection &d)
{
    const FieldTree &t = d.fields;
    Expected e;
    FieldValues &v = e.values;
    put(v, "mbtcp.trans_id", values(t, "mbap.transaction_id"));
    put(v, "mbtcp.prot_id", values(t, "mbap.protocol_id"));
    put(v, "mbtcp.len", values(t, "mbap.length"));
    put(v, "mbtcp.unit_id", values(t, "mbap.unit_id"));
    put(v, "mbrtu.unit_id", values(t, "rtu.unit_id"));
    if (const int c = t.indexOf("rtu.crc"); c >= 0) {
        const quint64 crc = t.at(c).value;
        put(v, "mbrtu.crc16", QString::number(((crc & 0xFF) << 8) | (crc >> 8)));
        // tshark's checksum status: 0 bad, 1 good.
        put(v, "mbrtu.crc16.status", QString::number(t.at(c).severity == Severity::Error ? 0 : 1));
    }
    if (t.indexOf("modbus.function_code") < 0)
        return e;
    const quint64 code = first(t, "modbus.function_code");
    put(v, "modbus.func_code", QString::number(code & 0x7F));
    if (code & 0x80) {
        put(v, "modbus.exception_code", values(t, "modbus.exception_code"));
        return e;
    }
    const bool response = d.direction == Direction::Response;
    switch (code) {
    case 0x01: case 0x02: {
        const char *bit = code == 0x01 ? "modbus.coil_value" : "modbus.discrete_input_value";
        put(v, "modbus.reference_num", values(t, "modbus.start_address"));
        put(v, "modbus.bit_cnt", values(t, "modbus.quantity"));
        put(v, "modbus.byte_cnt", values(t, "modbus.byte_count"));
        put(v, "modbus.bitnum", addresses(t, bit));
        put(v, "modbus.bitval", values(t, bit));
        break;
    }
    case 0x03: case 0x04: case 0x10:
        put(v, "modbus.reference_num", values(t, "modbus.start_address"));
        put(v, "modbus.word_cnt", values(t, "modbus.quantity"));
        put(v, "modbus.byte_cnt", values(t, "modbus.byte_count"));
        put(v, "modbus.regnum16", addresses(t, "modbus.register_value"));
        put(v, "modbus.regval_uint16", values(t, "modbus.register_value"));
        break;
    case 0x05: case 0x06:
        put(v, "modbus.reference_num", values(t, "modbus.address"));
        put(v, "modbus.data", raw(t, "modbus.value"));
        if (code == 0x05) // tshark names the value's second byte, 0x00 in FF00 and 0000, padding
            put(v, "modbus.padding", QString::number(first(t, "modbus.value") & 0xFF));
        break;
    case 0x07:
        put(v, "modbus.data", raw(t, "modbus.exception_status"));
        break;
    case 0x08:
        translateDiagnostics(t, response, v);
        break;
    case 0x0B: case 0x0C:
        put(v, "modbus.byte_cnt", values(t, "modbus.byte_count"));
        put(v, "modbus.ev_status", values(t, "modbus.status"));
        put(v, "modbus.ev_count", values(t, "modbus.event_count"));
        put(v, "modbus.ev_msg_count", values(t, "modbus.message_count"));
        put(v, "modbus.event", values(t, "modbus.event"));
        break;
    case 0x0F:
        put(v, "modbus.reference_num", values(t, "modbus.start_address"));
        put(v, "modbus.bit_cnt", values(t, "modbus.quantity"));
        put(v, "modbus.byte_cnt", values(t, "modbus.byte_count"));
        if (!response)
            put(v, "modbus.data", packedBits(t, "modbus.coil_value"));
        break;
    case 0x11: // tshark shows the whole response after the function code as data
        put(v, "modbus.data", raw(t, "modbus.byte_count") + raw(t, "modbus.server_id") + raw(t, "modbus.run_indicator")
                                  + raw(t, "modbus.additional_data"));
        break;
    case 0x14: case 0x15:
        translateFileRecords(t, code, response, e);
        break;
    case 0x16:
        put(v, "modbus.reference_num", values(t, "modbus.address"));
        put(v, "modbus.and_mask", values(t, "modbus.and_mask"));
        put(v, "modbus.or_mask", values(t, "modbus.or_mask"));
        break;
    case 0x17:
        put(v, "modbus.read_reference_num", values(t, "modbus.read_start_address"));
        put(v, "modbus.read_word_cnt", values(t, "modbus.read_quantity"));
        put(v, "modbus.write_reference_num", values(t, "modbus.write_start_address"));
        put(v, "modbus.write_word_cnt", values(t, "modbus.write_quantity"));
        put(v, "modbus.byte_cnt", values(t, "modbus.byte_count"));
        put(v, "modbus.data", raw(t, "modbus.register_value"));
        break;
    case 0x18:
        put(v, "modbus.reference_num", values(t, "modbus.fifo_address"));
        put(v, "modbus.byte_cnt_16", values(t, "modbus.byte_count"));
        put(v, "modbus.word_cnt", values(t, "modbus.fifo_count"));
        put(v, "modbus.data", raw(t, "modbus.register_value"));
        break;
    case 0x2B:
        translateDeviceId(t, v);
        break;
    default:
        put(v, "modbus.data", raw(t, "modbus.data"));
        break;
    }
    return e;
}


} // namespace mbscope::interop
