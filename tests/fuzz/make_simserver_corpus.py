#!/usr/bin/python3
"""Writes the seed corpus of fuzz_simserver (tests/fuzz/corpus/simserver): requests of every
function code the simulator implements, addressed to the conformance profile's units, in each
endpoint's framing, as the target's input layout wants them (see fuzz_simserver.cpp).

The PDUs are the MODBUS Application Protocol V1.1b3 examples (6.1-6.21), with addresses moved into
the conformance map where the example's fall outside it, plus requests the map refuses (unknown
address, read-only block, quantity 126, unsupported codes, unit 2's single function, an unknown
unit) and a serial broadcast. Run it again after changing it: it replaces the directory's files.

    /usr/bin/python3 tests/fuzz/make_simserver_corpus.py
"""
import pathlib

OUT = pathlib.Path(__file__).resolve().parent / "corpus" / "simserver"

ENDPOINTS = {"tcp": 0, "rtu-tcp": 1, "ascii-tcp": 2, "udp": 3, "rtu-udp": 4, "rtu": 5, "ascii": 6}

# (unit, PDU hex)
REQUESTS = [
    (1, "01 0000 0013"),                  # 6.1: coils
    (1, "02 0000 0016"),                  # 6.2: discrete inputs
    (1, "03 0000 000A"),                  # 6.3: holding registers
    (1, "03 00C8 0012"),                  #      the typed block
    (1, "04 000A 0014"),                  # 6.4: input registers
    (1, "05 0001 FF00"),                  # 6.5: coil ON
    (1, "06 0007 1092"),                  # 6.6
    (1, "07"),                            # 6.7: exception status
    (1, "08 0000 A537"),                  # 6.8: return query data
    (1, "08 000B 0000"),                  #      bus message count
    (1, "0B"),                            # 6.9: comm event counter
    (1, "0C"),                            # 6.10: comm event log
    (1, "0F 0013 000A 02 CD01"),          # 6.11
    (1, "10 0001 0002 04 000A 0102"),     # 6.12
    (1, "11"),                            # 6.13: report server id
    (1, "14 0E 06 0004 0001 0002 06 0003 0009 0002"),  # 6.14: read file record
    (1, "15 0D 06 0004 0007 0003 06AF 04BE 100D"),     # 6.15: write file record
    (1, "16 0004 00F2 0025"),             # 6.16: mask write
    (1, "17 0003 0006 000E 0003 06 00FF 00FF 00FF"),   # 6.17: read/write
    (1, "18 04DE"),                       # 6.18: FIFO
    (1, "2B 0E 01 00"),                   # 6.21: basic device identification
    (1, "2B 0E 03 00"),                   #       extended, several answers
    (1, "2B 0E 04 81"),                   #       one object
    (1, "03 0064 0001"),                  # outside the map: 02
    (1, "03 0000 007E"),                  # quantity 126: 03
    (1, "06 012C 0001"),                  # read-only block: 02
    (1, "2A 00"),                         # unsupported: 01
    (1, "08 0001 FF00"),                  # restart communications
    (2, "03 0000 0005"),                  # unit 2: 03 only
    (2, "01 0000 0001"),                  #         anything else: 01
    (9, "03 0000 0001"),                  # no unit 9: 0B, or silence on serial lines
    (0, "06 0001 0003"),                  # broadcast (serial framings), unit 0 routed on TCP
]


def crc16(data):
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def frame(endpoint, unit, pdu, tid):
    if endpoint in ("tcp", "udp"):
        return tid.to_bytes(2, "big") + b"\0\0" + (len(pdu) + 1).to_bytes(2, "big") + bytes([unit]) + pdu
    if endpoint in ("rtu-tcp", "rtu-udp", "rtu"):
        body = bytes([unit]) + pdu
        return body + crc16(body)
    body = bytes([unit]) + pdu
    lrc = (-sum(body)) & 0xFF
    return b":" + (body + bytes([lrc])).hex().upper().encode() + b"\r\n"


def stream(endpoint, requests, datagram):
    out = b""
    for tid, (unit, text) in enumerate(requests, start=1):
        f = frame(endpoint, unit, bytes.fromhex(text.replace(" ", "")), tid)
        out += bytes([len(f)]) + f if datagram else f
    return out


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.iterdir():
        old.unlink()
    for endpoint, number in ENDPOINTS.items():
        datagram = endpoint in ("udp", "rtu-udp")
        everything = stream(endpoint, REQUESTS, datagram)
        # Byte 1: chunking (bits 0-1), seed (2-5), silences (6), faults (7).
        variants = {"all-at-once": 0x03, "bytewise": 0x00, "random-chunks-silences": 0x46 | 0x08,
                    "faults": 0x83 | 0x14}
        for name, flags in variants.items():
            (OUT / f"{endpoint}-{name}").write_bytes(bytes([number, flags]) + everything)
        # Garbage between frames: a stream endpoint must resynchronise (MBAP closes instead).
        if not datagram:
            noisy = b"\xff\x00" + stream(endpoint, REQUESTS[:3], False) + b"\x13\x37garbage" \
                + stream(endpoint, REQUESTS[3:6], False)
            (OUT / f"{endpoint}-garbage").write_bytes(bytes([number, 0x03]) + noisy)
        for unit, text in REQUESTS:
            pdu = bytes.fromhex(text.replace(" ", ""))
            if endpoint in ("tcp", "rtu"):
                name = f"{endpoint}-unit{unit}-fc{pdu[0]:02x}-{pdu[1:].hex()[:12] or 'nodata'}"
                (OUT / name).write_bytes(bytes([number, 0x03]) + stream(endpoint, [(unit, text)], False))
    print(f"{len(list(OUT.iterdir()))} seeds in {OUT}")


if __name__ == "__main__":
    main()
