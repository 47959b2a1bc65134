#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "roundtripcheck.h"

#include <QtTest/QtTest>

#include <algorithm>

using namespace mbscope;

// Round trip for every public function code: random valid parameters (a fixed seed per code, so
// a failure repeats), the request and the response built from them, both dissected, and the
// same values read back by key. A valid PDU must dissect without any Error field.
namespace {

using namespace roundtrip;

constexpr int kIterations = 300;
constexpr quint32 kSeed = 0x6D627363; // "mbsc"

constexpr Direction Req = Direction::Request;
constexpr Direction Rsp = Direction::Response;

QList<quint64> bitValues(const QList<bool> &bits)
{
    QList<quint64> out;
    for (bool b : bits)
        out.append(b ? 1 : 0);
    return out;
}

// The padding bits field of the last data byte, present when the quantity is not a multiple of 8.
QList<quint64> padding(int quantity)
{
    return quantity % 8 == 0 ? QList<quint64>() : QList<quint64>{0};
}

// ---- one iteration per code; each returns through Trip's problem ----

void readBits(QRandomGenerator &rng, Trip &t, quint8 code)
{
    const int start = pick(rng, 0, 0xFFFF);
    const int quantity = pick(rng, 1, std::min(2000, 0x10000 - start));
    const QList<bool> bits = randomBits(rng, quantity);
    const bool coils = code == 0x01;
    const BuildResult request = coils ? RequestBuilder::readCoils(start, quantity)
                                      : RequestBuilder::readDiscreteInputs(start, quantity);
    t.dissect(request, Req);
    t.value("modbus.function_code", code);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
    const BuildResult response = coils ? ResponseBuilder::readCoils(bits) : ResponseBuilder::readDiscreteInputs(bits);
    t.dissect(response, Rsp, request.pdu);
    const char *key = coils ? "modbus.coil_value" : "modbus.discrete_input_value";
    t.value("modbus.byte_count", quint64((quantity + 7) / 8));
    t.values(key, bitValues(bits));
    t.addresses(key, run(start, quantity));
    t.values("modbus.padding_bits", padding(quantity));
}

void readRegisters(QRandomGenerator &rng, Trip &t, quint8 code)
{
    const int start = pick(rng, 0, 0xFFFF);
    const int quantity = pick(rng, 1, std::min(125, 0x10000 - start));
    const QList<quint16> values = randomWords(rng, quantity);
    const bool holding = code == 0x03;
    const BuildResult request = holding ? RequestBuilder::readHoldingRegisters(start, quantity)
                                        : RequestBuilder::readInputRegisters(start, quantity);
    t.dissect(request, Req);
    t.value("modbus.function_code", code);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
    const BuildResult response = holding ? ResponseBuilder::readHoldingRegisters(values)
                                         : ResponseBuilder::readInputRegisters(values);
    t.dissect(response, Rsp, request.pdu);
    t.value("modbus.byte_count", quint64(2 * quantity));
    t.values("modbus.register_value", widen(values));
    t.addresses("modbus.register_value", run(start, quantity));
}

void writeSingleCoil(QRandomGenerator &rng, Trip &t)
{
    const int address = pick(rng, 0, 0xFFFF);
    const bool on = rng.bounded(2u) == 1;
    const BuildResult request = RequestBuilder::writeSingleCoil(address, on);
    for (Direction d : {Req, Rsp}) {
        t.dissect(d == Req ? request : ResponseBuilder::writeSingleCoil(address, on), d,
                  d == Rsp ? request.pdu : QByteArray());
        t.value("modbus.address", quint64(address));
        t.value("modbus.value", on ? 0xFF00 : 0x0000);
        t.meanings("modbus.value", {on ? "ON" : "OFF"});
    }
}

void writeSingleRegister(QRandomGenerator &rng, Trip &t)
{
    const int address = pick(rng, 0, 0xFFFF);
    const int value = pick(rng, 0, 0xFFFF);
    const BuildResult request = RequestBuilder::writeSingleRegister(address, value);
    t.dissect(request, Req);
    t.value("modbus.address", quint64(address));
    t.value("modbus.value", quint64(value));
    t.dissect(ResponseBuilder::writeSingleRegister(address, value), Rsp, request.pdu);
    t.value("modbus.address", quint64(address));
    t.value("modbus.value", quint64(value));
}

void readExceptionStatus(QRandomGenerator &rng, Trip &t)
{
    const int outputs = pick(rng, 0, 0xFF);
    const BuildResult request = RequestBuilder::readExceptionStatus();
    t.dissect(request, Req);
    t.topLevel({"modbus.function_code"});
    t.dissect(ResponseBuilder::readExceptionStatus(outputs), Rsp, request.pdu);
    t.value("modbus.exception_status", quint64(outputs));
    QList<quint64> bits;
    for (int bit = 0; bit < 8; ++bit)
        bits.append((outputs >> bit) & 1);
    t.values("modbus.exception_status_bit", bits);
    t.addresses("modbus.exception_status_bit", run(0, 8));
}

void diagnostics(QRandomGenerator &rng, Trip &t)
{
    static const int subs[] = {0x00, 0x01, 0x02, 0x03, 0x04, 0x0A, 0x0B, 0x0C, 0x0D,
                               0x0E, 0x0F, 0x10, 0x11, 0x12, 0x14};
    const int sub = subs[rng.bounded(quint32(std::size(subs)))];
    QByteArray data(2, '\0');
    if (sub == 0x00)
        data = randomBytes(rng, 2 * pick(rng, 0, 125));
    else if (sub == 0x01)
        data = QByteArray::fromHex(rng.bounded(2u) ? "FF00" : "0000");
    else if (sub == 0x03)
        data[0] = char(rng.bounded(256u));
    const BuildResult request = RequestBuilder::diagnostics(sub, data);
    const int word = pick(rng, 0, 0xFFFF);
    const bool returnsValue = sub == 0x02 || (sub >= 0x0B && sub <= 0x12);
    QByteArray answer = data;
    if (returnsValue) {
        answer[0] = char(word >> 8);
        answer[1] = char(word);
    }
    for (Direction d : {Req, Rsp}) {
        if (d == Rsp && sub == 0x04)
            break; // Force Listen Only Mode has no response
        t.dissect(d == Req ? request : ResponseBuilder::diagnostics(sub, answer), d,
                  d == Rsp ? request.pdu : QByteArray());
        t.value("modbus.subfunction", quint64(sub));
        const QByteArray &sent = d == Req ? data : answer;
        if (sub == 0x00) {
            t.rawOrAbsent("modbus.echo_data", sent);
        } else if (sub == 0x01) {
            t.value("modbus.restart_option", sent == QByteArray::fromHex("FF00") ? 0xFF00 : 0x0000);
        } else if (sub == 0x03) {
            t.value("modbus.ascii_delimiter", quint8(sent.at(0)));
            t.value("modbus.padding", 0);
        } else if (d == Rsp && sub == 0x02) {
            t.value("modbus.diagnostic_register", quint64(word));
        } else if (d == Rsp && returnsValue) {
            t.value("modbus.counter_value", quint64(word));
        } else {
            t.value("modbus.diagnostic_data", 0);
        }
    }
}

void commEventCounter(QRandomGenerator &rng, Trip &t)
{
    const bool busy = rng.bounded(2u) == 1;
    const int events = pick(rng, 0, 0xFFFF);
    const BuildResult request = RequestBuilder::getCommEventCounter();
    t.dissect(request, Req);
    t.topLevel({"modbus.function_code"});
    t.dissect(ResponseBuilder::getCommEventCounter(busy, events), Rsp, request.pdu);
    t.value("modbus.status", busy ? 0xFFFF : 0x0000);
    t.value("modbus.event_count", quint64(events));
}

void commEventLog(QRandomGenerator &rng, Trip &t)
{
    const bool busy = rng.bounded(2u) == 1;
    const int eventCount = pick(rng, 0, 0xFFFF);
    const int messageCount = pick(rng, 0, 0xFFFF);
    const QByteArray events = randomBytes(rng, pick(rng, 0, 64));
    const BuildResult request = RequestBuilder::getCommEventLog();
    t.dissect(request, Req);
    t.topLevel({"modbus.function_code"});
    t.dissect(ResponseBuilder::getCommEventLog(busy, eventCount, messageCount, events), Rsp, request.pdu);
    t.value("modbus.byte_count", quint64(6 + events.size()));
    t.value("modbus.status", busy ? 0xFFFF : 0x0000);
    t.value("modbus.event_count", quint64(eventCount));
    t.value("modbus.message_count", quint64(messageCount));
    QList<quint64> bytes;
    for (char c : events)
        bytes.append(quint8(c));
    t.values("modbus.event", bytes);
    t.addresses("modbus.event", run(0, int(events.size())));
}

void writeMultipleCoils(QRandomGenerator &rng, Trip &t)
{
    const int start = pick(rng, 0, 0xFFFF);
    const int quantity = pick(rng, 1, std::min(1968, 0x10000 - start));
    const QList<bool> bits = randomBits(rng, quantity);
    const BuildResult request = RequestBuilder::writeMultipleCoils(start, bits);
    t.dissect(request, Req);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
    t.value("modbus.byte_count", quint64((quantity + 7) / 8));
    t.values("modbus.coil_value", bitValues(bits));
    t.addresses("modbus.coil_value", run(start, quantity));
    t.values("modbus.padding_bits", padding(quantity));
    t.dissect(ResponseBuilder::writeMultipleCoils(start, quantity), Rsp, request.pdu);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
}

void writeMultipleRegisters(QRandomGenerator &rng, Trip &t)
{
    const int start = pick(rng, 0, 0xFFFF);
    const int quantity = pick(rng, 1, std::min(123, 0x10000 - start));
    const QList<quint16> values = randomWords(rng, quantity);
    const BuildResult request = RequestBuilder::writeMultipleRegisters(start, values);
    t.dissect(request, Req);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
    t.value("modbus.byte_count", quint64(2 * quantity));
    t.values("modbus.register_value", widen(values));
    t.addresses("modbus.register_value", run(start, quantity));
    t.dissect(ResponseBuilder::writeMultipleRegisters(start, quantity), Rsp, request.pdu);
    t.value("modbus.start_address", quint64(start));
    t.value("modbus.quantity", quint64(quantity));
}

void reportServerId(QRandomGenerator &rng, Trip &t)
{
    // The dissector reads a one-byte server ID (pdureportserverid.cpp: the layout of libmodbus,
    // FreeModbus and Wireshark), so the round trip uses one.
    const QByteArray serverId = randomBytes(rng, 1);
    const bool running = rng.bounded(2u) == 1;
    const QByteArray additional = randomBytes(rng, pick(rng, 0, 249));
    const BuildResult request = RequestBuilder::reportServerId();
    t.dissect(request, Req);
    t.topLevel({"modbus.function_code"});
    t.dissect(ResponseBuilder::reportServerId(serverId, running, additional), Rsp, request.pdu);
    t.value("modbus.byte_count", quint64(2 + additional.size()));
    t.raws("modbus.server_id", {serverId});
    t.value("modbus.run_indicator", running ? 0xFF : 0x00);
    t.rawOrAbsent("modbus.additional_data", additional);
}

// Record lengths for n sub-requests whose registers, at 2 bytes each plus overhead bytes per
// sub-request, fit in room bytes: each at least 1 and at most maxLength.
QList<int> recordLengths(QRandomGenerator &rng, int n, int overhead, int room, int maxLength)
{
    int budget = (room - overhead * n) / 2;
    QList<int> lengths;
    for (int i = 0; i < n; ++i) {
        const int most = std::min(maxLength, budget - (n - i - 1));
        const int length = pick(rng, 1, most);
        lengths.append(length);
        budget -= length;
    }
    return lengths;
}

void readFileRecord(QRandomGenerator &rng, Trip &t)
{
    // Response data: 2 bytes plus the registers per sub-response, within 251 bytes.
    const int n = pick(rng, 1, 35);
    const QList<int> lengths = recordLengths(rng, n, 2, 251, 124);
    QList<FileRecordRead> subs;
    QList<QList<quint16>> records;
    QList<quint64> files, numbers, flat;
    QList<int> addresses;
    for (int length : lengths) {
        const FileRecordRead s{pick(rng, 1, 0xFFFF), pick(rng, 0, 10000 - length), length};
        subs.append(s);
        files.append(quint64(s.fileNumber));
        numbers.append(quint64(s.recordNumber));
        records.append(randomWords(rng, length));
        flat += widen(records.last());
        addresses += run(s.recordNumber, length);
    }
    const BuildResult request = RequestBuilder::readFileRecord(subs);
    t.dissect(request, Req);
    t.value("modbus.byte_count", quint64(7 * n));
    t.values("modbus.reference_type", QList<quint64>(n, 6));
    t.values("modbus.file_number", files);
    t.values("modbus.record_number", numbers);
    t.values("modbus.record_length", widen(lengths));
    t.values("modbus.file_subrequest", QList<quint64>(n, 0));
    t.dissect(ResponseBuilder::readFileRecord(records), Rsp, request.pdu);
    qint64 dataLength = 0;
    QList<quint64> subLengths;
    for (int length : lengths) {
        dataLength += 2 + 2 * length;
        subLengths.append(quint64(1 + 2 * length));
    }
    t.value("modbus.byte_count", quint64(dataLength));
    t.values("modbus.file_subresponse", QList<quint64>(n, 0));
    t.values("modbus.subresponse_length", subLengths);
    t.values("modbus.reference_type", QList<quint64>(n, 6));
    t.values("modbus.register_value", flat);
    t.addresses("modbus.register_value", addresses);
}

void writeFileRecord(QRandomGenerator &rng, Trip &t)
{
    // Request data: 7 bytes plus the registers per sub-request, within 251 bytes.
    const int n = pick(rng, 1, 27);
    const QList<int> lengths = recordLengths(rng, n, 7, 251, 122);
    QList<FileRecordWrite> subs;
    QList<quint64> files, numbers, flat;
    QList<int> addresses;
    qint64 dataLength = 0;
    for (int length : lengths) {
        FileRecordWrite s{pick(rng, 1, 0xFFFF), pick(rng, 0, 10000 - length), randomWords(rng, length)};
        files.append(quint64(s.fileNumber));
        numbers.append(quint64(s.recordNumber));
        flat += widen(s.values);
        addresses += run(s.recordNumber, length);
        dataLength += 7 + 2 * length;
        subs.append(s);
    }
    const BuildResult request = RequestBuilder::writeFileRecord(subs);
    for (Direction d : {Req, Rsp}) {
        t.dissect(d == Req ? request : ResponseBuilder::writeFileRecord(subs), d, d == Rsp ? request.pdu : QByteArray());
        t.value("modbus.byte_count", quint64(dataLength));
        t.values(d == Req ? "modbus.file_subrequest" : "modbus.file_subresponse", QList<quint64>(n, 0));
        t.values("modbus.reference_type", QList<quint64>(n, 6));
        t.values("modbus.file_number", files);
        t.values("modbus.record_number", numbers);
        t.values("modbus.record_length", widen(lengths));
        t.values("modbus.register_value", flat);
        t.addresses("modbus.register_value", addresses);
    }
}

void maskWriteRegister(QRandomGenerator &rng, Trip &t)
{
    const int address = pick(rng, 0, 0xFFFF);
    const int andMask = pick(rng, 0, 0xFFFF);
    const int orMask = pick(rng, 0, 0xFFFF);
    const BuildResult request = RequestBuilder::maskWriteRegister(address, andMask, orMask);
    for (Direction d : {Req, Rsp}) {
        t.dissect(d == Req ? request : ResponseBuilder::maskWriteRegister(address, andMask, orMask), d,
                  d == Rsp ? request.pdu : QByteArray());
        t.value("modbus.address", quint64(address));
        t.value("modbus.and_mask", quint64(andMask));
        t.value("modbus.or_mask", quint64(orMask));
    }
}

void readWriteMultipleRegisters(QRandomGenerator &rng, Trip &t)
{
    const int readStart = pick(rng, 0, 0xFFFF);
    const int readQuantity = pick(rng, 1, std::min(125, 0x10000 - readStart));
    const int writeStart = pick(rng, 0, 0xFFFF);
    const QList<quint16> written = randomWords(rng, pick(rng, 1, std::min(121, 0x10000 - writeStart)));
    const QList<quint16> read = randomWords(rng, readQuantity);
    const BuildResult request = RequestBuilder::readWriteMultipleRegisters(readStart, readQuantity, writeStart, written);
    t.dissect(request, Req);
    t.value("modbus.read_start_address", quint64(readStart));
    t.value("modbus.read_quantity", quint64(readQuantity));
    t.value("modbus.write_start_address", quint64(writeStart));
    t.value("modbus.write_quantity", quint64(written.size()));
    t.value("modbus.byte_count", quint64(2 * written.size()));
    t.values("modbus.register_value", widen(written));
    t.addresses("modbus.register_value", run(writeStart, int(written.size())));
    t.dissect(ResponseBuilder::readWriteMultipleRegisters(read), Rsp, request.pdu);
    t.value("modbus.byte_count", quint64(2 * readQuantity));
    t.values("modbus.register_value", widen(read));
    t.addresses("modbus.register_value", run(readStart, readQuantity));
}

void readFifoQueue(QRandomGenerator &rng, Trip &t)
{
    const int address = pick(rng, 0, 0xFFFF);
    const QList<quint16> queue = randomWords(rng, pick(rng, 0, 31));
    const BuildResult request = RequestBuilder::readFifoQueue(address);
    t.dissect(request, Req);
    t.value("modbus.fifo_address", quint64(address));
    t.dissect(ResponseBuilder::readFifoQueue(queue), Rsp, request.pdu);
    t.value("modbus.byte_count", quint64(2 + 2 * queue.size()));
    t.value("modbus.fifo_count", quint64(queue.size()));
    t.values("modbus.register_value", widen(queue));
    t.addresses("modbus.register_value", run(0, int(queue.size())));
}

// An object ID that is not reserved (0x07-0x7F are; the dissector warns about them).
int objectIdAtLeast(QRandomGenerator &rng, int min)
{
    int id = pick(rng, min, 0xFF);
    if (id >= 0x07 && id <= 0x7F)
        id = 0x80 + int(rng.bounded(0x80u));
    return std::max(id, min);
}

void readDeviceIdentification(QRandomGenerator &rng, Trip &t)
{
    const int code = pick(rng, 1, 4);
    const bool individual = code == 4;
    const int firstId = objectIdAtLeast(rng, 0);
    const BuildResult request = RequestBuilder::readDeviceIdentification(code, firstId);
    t.dissect(request, Req);
    t.value("modbus.mei_type", 0x0E);
    t.value("modbus.read_device_id_code", quint64(code));
    t.value("modbus.object_id", quint64(firstId));

    // Objects in increasing ID order from the one asked for, within 246 bytes (253 - 7).
    static const int levels[] = {0x01, 0x02, 0x03, 0x81, 0x82, 0x83};
    const int level = individual ? 0x81 + int(rng.bounded(3u)) : levels[rng.bounded(6u)];
    QList<DeviceIdObject> objects;
    int room = 246;
    int id = firstId;
    const int wanted = individual ? 1 : pick(rng, 1, 8);
    while (int(objects.size()) < wanted && id <= 0xFF && room >= 2) {
        const QByteArray value = randomBytes(rng, pick(rng, 0, std::min(room - 2, individual ? 244 : 40)));
        objects.append({id, value});
        room -= 2 + int(value.size());
        if (id == 0xFF)
            break;
        id = objectIdAtLeast(rng, id + 1);
    }
    const int last = objects.last().id;
    const bool moreFollows = !individual && last < 0xFF && rng.bounded(2u) == 1;
    const int next = moreFollows ? objectIdAtLeast(rng, last + 1) : 0;
    t.dissect(ResponseBuilder::readDeviceIdentification(code, level, moreFollows, next, objects), Rsp, request.pdu);
    t.value("modbus.mei_type", 0x0E);
    t.value("modbus.read_device_id_code", quint64(code));
    t.value("modbus.conformity_level", quint64(level));
    t.value("modbus.more_follows", moreFollows ? 0xFF : 0x00);
    t.value("modbus.next_object_id", quint64(next));
    t.value("modbus.object_count", quint64(objects.size()));
    QList<quint64> ids, lengths;
    QList<QByteArray> values;
    for (const DeviceIdObject &o : objects) {
        ids.append(quint64(o.id));
        lengths.append(quint64(o.value.size()));
        values.append(o.value);
    }
    t.values("modbus.object", QList<quint64>(objects.size(), 0));
    t.addresses("modbus.object", run(0, int(objects.size())));
    t.values("modbus.object_id", ids);
    t.values("modbus.object_length", lengths);
    t.raws("modbus.object_value", values);
}

void canopenGeneralReference(QRandomGenerator &rng, Trip &t)
{
    const QByteArray data = randomBytes(rng, pick(rng, 0, 251));
    const QByteArray answer = randomBytes(rng, pick(rng, 0, 251));
    const BuildResult request = RequestBuilder::canopenGeneralReference(data);
    t.dissect(request, Req);
    t.value("modbus.mei_type", 0x0D);
    t.rawOrAbsent("modbus.data", data);
    t.dissect(ResponseBuilder::canopenGeneralReference(answer), Rsp, request.pdu);
    t.value("modbus.mei_type", 0x0D);
    t.rawOrAbsent("modbus.data", answer);
}

void userDefined(QRandomGenerator &rng, Trip &t)
{
    static const int codes[] = {65, 66, 67, 68, 69, 70, 71, 72, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110};
    const int code = codes[rng.bounded(quint32(std::size(codes)))];
    const QByteArray data = randomBytes(rng, pick(rng, 0, 252));
    const QByteArray answer = randomBytes(rng, pick(rng, 0, 252));
    const BuildResult request = RequestBuilder::userDefined(code, data);
    t.dissect(request, Req);
    t.value("modbus.function_code", quint64(code));
    t.rawOrAbsent("modbus.data", data);
    t.dissect(ResponseBuilder::userDefined(code, answer), Rsp, request.pdu);
    t.value("modbus.function_code", quint64(code));
    t.rawOrAbsent("modbus.data", answer);
}

void exception(QRandomGenerator &rng, Trip &t)
{
    static const int codes[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0B, 0x0C,
                                0x0F, 0x10, 0x11, 0x14, 0x15, 0x16, 0x17, 0x18, 0x2B};
    const int function = codes[rng.bounded(quint32(std::size(codes)))];
    const int exceptionCode = pick(rng, 0, 0xFF);
    const QByteArray request(1, char(function));
    t.dissect(ResponseBuilder::exception(function, exceptionCode), Rsp, request);
    t.value("modbus.function_code", quint64(function | 0x80));
    t.value("modbus.request_function_code", quint64(function));
    t.value("modbus.exception_code", quint64(exceptionCode));
}

} // namespace

class TestRoundTrip : public QObject
{
    Q_OBJECT
private slots:
    void roundTrip_data();
    void roundTrip();
};

void TestRoundTrip::roundTrip_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("mei");
    const int codes[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0B, 0x0C,
                         0x0F, 0x10, 0x11, 0x14, 0x15, 0x16, 0x17, 0x18};
    for (int code : codes)
        QTest::addRow("%02X", code) << code << 0;
    QTest::newRow("2B/0E") << 0x2B << 0x0E;
    QTest::newRow("2B/0D") << 0x2B << 0x0D;
    QTest::newRow("user-defined 41-48, 64-6E") << 0x41 << 0;
    QTest::newRow("exception 80+code") << 0x80 << 0;
}

void TestRoundTrip::roundTrip()
{
    QFETCH(int, code);
    QFETCH(int, mei);
    QRandomGenerator rng(kSeed + quint32(code << 8) + quint32(mei));
    QString problem;
    for (int i = 0; i < kIterations && problem.isEmpty(); ++i) {
        Trip t(&problem, i);
        switch (code) {
        case 0x01: case 0x02: readBits(rng, t, quint8(code)); break;
        case 0x03: case 0x04: readRegisters(rng, t, quint8(code)); break;
        case 0x05: writeSingleCoil(rng, t); break;
        case 0x06: writeSingleRegister(rng, t); break;
        case 0x07: readExceptionStatus(rng, t); break;
        case 0x08: diagnostics(rng, t); break;
        case 0x0B: commEventCounter(rng, t); break;
        case 0x0C: commEventLog(rng, t); break;
        case 0x0F: writeMultipleCoils(rng, t); break;
        case 0x10: writeMultipleRegisters(rng, t); break;
        case 0x11: reportServerId(rng, t); break;
        case 0x14: readFileRecord(rng, t); break;
        case 0x15: writeFileRecord(rng, t); break;
        case 0x16: maskWriteRegister(rng, t); break;
        case 0x17: readWriteMultipleRegisters(rng, t); break;
        case 0x18: readFifoQueue(rng, t); break;
        case 0x2B:
            if (mei == 0x0E)
                readDeviceIdentification(rng, t);
            else
                canopenGeneralReference(rng, t);
            break;
        case 0x41: userDefined(rng, t); break;
        case 0x80: exception(rng, t); break;
        default: QFAIL("no round trip for this code");
        }
    }
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

QTEST_GUILESS_MAIN(TestRoundTrip)
#include "tst_roundtrip.moc"
