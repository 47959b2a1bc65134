#pragma once

// The exchanges tst_tshark writes into captures for tshark's Modbus dissector. Each is a request
// PDU and its response PDU (function code first); the test wraps them in an MBAP header (Modbus
// TCP, port 502) and in unit + CRC (RTU over TCP), so every row is compared in both framings
// unless marked otherwise.
//
// Sources:
//  - "spec 6.x": the example in that section of the MODBUS Application Protocol Specification
//    V1.1b3, copied byte for byte (6.21's object lengths corrected: its example announces 0x0D
//    bytes for the 15-character "Product code XX").
//  - "spec 6.x (built)": built by hand from the field layout that section gives, for codes or
//    sub-functions the specification shows no bytes for.
//  - "spec 7 (built)": exception responses, function code + 0x80 and an exception code from 7.
//  - "published: <id>": frames from tests/data/published-frames.json (the lab papers it cites),
//    PDU taken from the published ADU unchanged.

namespace mbscope::interop {

struct TsharkExchange {
    const char *source;
    int unit;
    const char *request;  // PDU hex
    const char *response; // PDU hex, nullptr when the request gets no answer
    bool tcp = true;      // write it as Modbus TCP
    bool rtu = true;      // write it as RTU over TCP
    bool badCrc = false;  // RTU only: the response's CRC is sent wrong on purpose
};

// "Company identification", "Product code XX", "V2.11" as hex, for 2B/0E.
#define MBSCOPE_COMPANY "43 6F 6D 70 61 6E 79 20 69 64 65 6E 74 69 66 69 63 61 74 69 6F 6E"
#define MBSCOPE_PRODUCT "50 72 6F 64 75 63 74 20 63 6F 64 65 20 58 58"
#define MBSCOPE_VERSION_TEXT "56 32 2E 31 31"

inline const TsharkExchange kTsharkExchanges[] = {
    // 01 Read Coils, 02 Read Discrete Inputs, 03/04 read registers
    {"spec 6.1", 1, "01 00 13 00 13", "01 03 CD 6B 05"},
    {"spec 6.2", 1, "02 00 C4 00 16", "02 03 AC DB 35"},
    {"spec 6.3", 1, "03 00 6B 00 03", "03 06 02 2B 00 00 00 64"},
    {"spec 6.4", 1, "04 00 08 00 01", "04 02 00 0A"},
    {"spec 6.1 (built)", 17, "01 FF F0 00 10", "01 02 01 80"},
    {"spec 6.3 (built): 125 registers, the most one read may ask", 247, "03 00 00 00 7D",
     "03 FA 00 00 00 01 00 02 00 03 00 04 00 05 00 06 00 07 00 08 00 09 00 0A 00 0B 00 0C 00 0D 00 0E 00 0F 00 10"
     " 00 11 00 12 00 13 00 14 00 15 00 16 00 17 00 18 00 19 00 1A 00 1B 00 1C 00 1D 00 1E 00 1F 00 20 00 21 00 22"
     " 00 23 00 24 00 25 00 26 00 27 00 28 00 29 00 2A 00 2B 00 2C 00 2D 00 2E 00 2F 00 30 00 31 00 32 00 33 00 34"
     " 00 35 00 36 00 37 00 38 00 39 00 3A 00 3B 00 3C 00 3D 00 3E 00 3F 00 40 00 41 00 42 00 43 00 44 00 45 00 46"
     " 00 47 00 48 00 49 00 4A 00 4B 00 4C 00 4D 00 4E 00 4F 00 50 00 51 00 52 00 53 00 54 00 55 00 56 00 57 00 58"
     " 00 59 00 5A 00 5B 00 5C 00 5D 00 5E 00 5F 00 60 00 61 00 62 00 63 00 64 00 65 00 66 00 67 00 68 00 69 00 6A"
     " 00 6B 00 6C 00 6D 00 6E 00 6F 00 70 00 71 00 72 00 73 00 74 00 75 00 76 00 77 00 78 00 79 FF FF 80 00 7F FF"},
    // 05/06 single writes: the response echoes the request
    {"spec 6.5", 1, "05 00 AC FF 00", "05 00 AC FF 00"},
    {"spec 6.5 (built): OFF", 1, "05 00 AD 00 00", "05 00 AD 00 00"},
    {"spec 6.6", 1, "06 00 01 00 03", "06 00 01 00 03"},
    // 07 Read Exception Status (serial line)
    {"spec 6.7", 1, "07", "07 6D"},
    // 08 Diagnostics, every sub-function of 6.8.1
    {"spec 6.8", 1, "08 00 00 A5 37", "08 00 00 A5 37"},
    {"spec 6.8.1 sub 01 (built)", 1, "08 00 01 FF 00", "08 00 01 FF 00"},
    {"spec 6.8.1 sub 01 (built)", 1, "08 00 01 00 00", "08 00 01 00 00"},
    {"spec 6.8.1 sub 02 (built)", 1, "08 00 02 00 00", "08 00 02 12 34"},
    {"spec 6.8.1 sub 03 (built)", 1, "08 00 03 3B 00", "08 00 03 3B 00"},
    {"spec 6.8.1 sub 04 (built): no response", 1, "08 00 04 00 00", nullptr},
    {"spec 6.8.1 sub 0A (built)", 1, "08 00 0A 00 00", "08 00 0A 00 00"},
    {"spec 6.8.1 sub 0B (built)", 1, "08 00 0B 00 00", "08 00 0B 01 05"},
    {"spec 6.8.1 sub 0C (built)", 1, "08 00 0C 00 00", "08 00 0C 00 06"},
    {"spec 6.8.1 sub 0D (built)", 1, "08 00 0D 00 00", "08 00 0D 00 07"},
    {"spec 6.8.1 sub 0E (built)", 1, "08 00 0E 00 00", "08 00 0E 00 08"},
    {"spec 6.8.1 sub 0F (built)", 1, "08 00 0F 00 00", "08 00 0F 00 09"},
    {"spec 6.8.1 sub 10 (built)", 1, "08 00 10 00 00", "08 00 10 00 0A"},
    {"spec 6.8.1 sub 11 (built)", 1, "08 00 11 00 00", "08 00 11 00 0B"},
    {"spec 6.8.1 sub 12 (built)", 1, "08 00 12 00 00", "08 00 12 FF FE"},
    {"spec 6.8.1 sub 14 (built)", 1, "08 00 14 00 00", "08 00 14 00 00"},
    // 0B, 0C comm event counter and log (serial line)
    {"spec 6.9", 1, "0B", "0B FF FF 01 08"},
    {"spec 6.10", 1, "0C", "0C 08 00 00 01 08 01 21 20 00"},
    // 0F/10 multiple writes
    {"spec 6.11", 1, "0F 00 13 00 0A 02 CD 01", "0F 00 13 00 0A"},
    {"spec 6.12", 1, "10 00 01 00 02 04 00 0A 01 02", "10 00 01 00 02"},
    // 11 Report Server ID (serial line): one-byte server id, run indicator ON, 2 bytes of device data
    {"spec 6.13 (built)", 1, "11", "11 04 2A FF 01 02"},
    // 14/15 file records
    {"spec 6.14", 1, "14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 02", "14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40"},
    {"spec 6.15", 1, "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D", "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D"},
    // 16 mask write, 17 read/write, 18 FIFO
    {"spec 6.16", 1, "16 00 04 00 F2 00 25", "16 00 04 00 F2 00 25"},
    {"spec 6.17", 1, "17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF", "17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF"},
    {"spec 6.18", 1, "18 04 DE", "18 00 06 00 02 01 B8 12 84"},
    // 2B/0E device identification: basic stream, stream with more to follow, individual access
    {"spec 6.21", 1, "2B 0E 01 00",
     "2B 0E 01 01 00 00 03 00 16 " MBSCOPE_COMPANY " 01 0F " MBSCOPE_PRODUCT " 02 05 " MBSCOPE_VERSION_TEXT},
    {"spec 6.21 (built): more follows", 1, "2B 0E 01 00", "2B 0E 01 81 FF 02 02 00 16 " MBSCOPE_COMPANY " 01 0F " MBSCOPE_PRODUCT},
    {"spec 6.21 (built): individual access", 1, "2B 0E 04 01", "2B 0E 04 81 00 00 01 01 0F " MBSCOPE_PRODUCT},
    // 2B/0D CANopen general reference: carried raw
    {"spec 6.20 (built)", 1, "2B 0D 01 02", "2B 0D 01 02 03"},
    // user-defined codes 65-72 and 100-110: raw data
    {"spec 5 (built): user-defined 0x41", 1, "41 01 02", "41 03 04"},
    {"spec 5 (built): user-defined 0x64", 1, "64 AA BB", "64 CC"},
    // exceptions: every exception code of section 7, on every public function
    {"spec 7 (built)", 1, "01 00 13 00 13", "81 01"},
    {"spec 7 (built)", 1, "02 00 C4 00 16", "82 02"},
    {"spec 7", 10, "01 04 A1 00 01", "81 02"},
    {"spec 7 (built)", 1, "03 00 6B 00 03", "83 03"},
    {"spec 7 (built)", 1, "04 00 08 00 01", "84 04"},
    {"spec 7 (built)", 1, "05 00 AC FF 00", "85 05"},
    {"spec 7 (built)", 1, "06 00 01 00 03", "86 06"},
    {"spec 7 (built)", 1, "07", "87 04"},
    {"spec 7 (built)", 1, "08 00 00 A5 37", "88 01"},
    {"spec 7 (built)", 1, "0B", "8B 04"},
    {"spec 7 (built)", 1, "0C", "8C 06"},
    {"spec 7 (built)", 1, "0F 00 13 00 0A 02 CD 01", "8F 02"},
    {"spec 7 (built)", 1, "10 00 01 00 02 04 00 0A 01 02", "90 03"},
    {"spec 7 (built)", 1, "11", "91 01"},
    {"spec 7 (built)", 1, "14 07 06 00 04 00 01 00 02", "94 08"},
    {"spec 7 (built)", 1, "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D", "95 08"},
    {"spec 7 (built)", 1, "16 00 04 00 F2 00 25", "96 02"},
    {"spec 7 (built)", 1, "17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF", "97 03"},
    {"spec 7 (built)", 1, "18 04 DE", "98 03"},
    {"spec 7 (built)", 1, "2B 0E 01 00", "AB 02"},
    {"spec 7 (built): gateway path unavailable", 1, "03 00 00 00 01", "83 0A"},
    {"spec 7 (built): gateway target failed to respond", 1, "03 00 00 00 01", "83 0B"},
    {"spec 7 (built): user-defined code", 1, "41 01 02", "C1 01"},
    // published frames
    {"published: rosrao-read-request, with the 22 registers the printed response lost two of "
     "(its 20 printed registers, then 2 zero registers)", 1, "03 00 79 00 16",
     "03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 00 00 00 00 00 00"
     " 00 00 00 00 00 00 00 00 00 00 00 00"},
    {"published: arduino-read-request/response", 1, "03 00 00 00 04", "03 08 00 45 00 4E 00 01 00 01"},
    {"published: tutorial-holding-request/response", 7, "03 00 C8 00 04", "03 08 00 07 00 06 00 05 00 04"},
    {"published: tutorial-input-request/response", 7, "04 01 2C 00 03", "04 06 03 E8 01 F4 00 0A"},
    // The M221 talks Modbus TCP to unit 0, which on a serial line would be a broadcast.
    {"published: m221-write-words-request/reply", 0, "10 00 00 00 01 02 00 CD", "10 00 00 00 01", true, false},
    {"published: m221-write-bits-request/reply-pdu", 0, "0F 00 00 00 01 01 01", "0F 00 00 00 01", true, false},
    // a response whose CRC is wrong on purpose: both must say so
    {"spec 6.3 (built): wrong CRC", 1, "03 00 6B 00 02", "03 04 02 2B 00 00", false, true, true},
};

#undef MBSCOPE_COMPANY
#undef MBSCOPE_PRODUCT
#undef MBSCOPE_VERSION_TEXT

} // namespace mbscope::interop
