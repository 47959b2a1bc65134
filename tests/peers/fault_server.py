#!/usr/bin/python3
"""A Modbus server that misbehaves on purpose, for mbscope's fault tests.

  fault_server.py tcp|rtu-tcp [--port 0] [--unit 1] [--fault NAME[=PARAM]] [--lifetime S]
                  [--drop-at N[,N...]] [--die-at N]

Binds 127.0.0.1 (port 0 lets the system choose) and prints "LISTENING 127.0.0.1:PORT" on stdout.
tcp speaks MBAP (Messaging on TCP/IP V1.0b); rtu-tcp speaks RTU frames with CRC over the TCP stream
(MODBUS over Serial Line V1.02, 2.5.1), as a serial device server does.

It serves the data map of peer_datamap.h for 03 (holding registers, 1000 + 3a) and 04 (input
registers, 40000 + 2a) over PEER_TABLE_SIZE addresses, stores 06 and 10 writes, and answers
exception 01 to any other function code, 02 past the table's end. Only unit --unit answers when no
fault says otherwise; requests for other units are ignored.

Faults. --fault applies to every request of the run. While running, a line on standard input

  next NAME [PARAM]     applies NAME to the next request only (any connection), then back to normal
  always NAME [PARAM]   applies NAME to every request from now on ("always none" restores order)

is acknowledged by "OK next NAME PARAM" (or "ERR what") on stdout once armed, so a test waits for the
acknowledgement before it sends the request. After each answered (or swallowed) request the server
prints "SERVED N NAME" (N counts requests from 1) so tests can tell when a slow fault has finished.

  none              the correct answer
  close             half of the answer, then the connection is closed (mid-frame)
  silent            no answer at all; the connection stays open
  trickle [MS=20]   the correct answer one byte every MS milliseconds (slower than t1.5 at any baud
                    rate above 1200: MODBUS over Serial Line V1.02, 2.5.1.1)
  garbage [N=7]     N bytes of noise (DE AD BE EF 55 AA 13, repeated), then the correct answer
  wrong-tid         the answer with the MBAP transaction id plus one (tcp only)
  wrong-unit        the answer with the unit id plus one
  wrong-function    the answer with the function code of the other read (03 <-> 04, else 03)
  twice             the correct answer, sent twice back to back
  delay [MS=1500]   the correct answer after MS milliseconds (longer than the client's timeout)
  bad-crc           the answer with its CRC inverted (rtu-tcp only)
  exception [CODE=2]  an exception response with CODE
  short             a read answer holding one register fewer than asked (byte count consistent)
  echo              the request's own bytes sent back, whatever its unit (a 2-wire adapter that
                    hears itself)

A device that drops or dies. --drop-at N[,N...] closes the connection instead of answering request
N (counted as SERVED counts them) and serves on (a device restarting); --die-at N closes the
connection instead of answering request N, and the listening port with it: every later connection
is refused (a device gone), while the process waits for its standard input to close.

The process exits when its standard input closes (the test that started it died) or after --lifetime
seconds.
"""

import argparse
import asyncio
import struct
import sys

TABLE_SIZE = 10000  # PEER_TABLE_SIZE
GARBAGE = bytes([0xDE, 0xAD, 0xBE, 0xEF, 0x55, 0xAA, 0x13])
DEFAULT_PARAM = {"trickle": 20, "garbage": 7, "delay": 1500, "exception": 2}
FAULTS = ("none", "close", "silent", "trickle", "garbage", "wrong-tid", "wrong-unit",
          "wrong-function", "twice", "delay", "bad-crc", "exception", "short", "echo")


def holding_register(address):
    return (1000 + 3 * address) & 0xFFFF


def input_register(address):
    return (40000 + 2 * address) & 0xFFFF


def crc16(data):
    """CRC-16/MODBUS (MODBUS over Serial Line V1.02, 6.2.2), appended low byte first."""
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def say(line):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()


class Faults:
    """Which fault the next request gets: a one-shot fault first, else the standing one."""

    def __init__(self, mode, standing):
        self.mode = mode
        self.standing = standing
        self.once = None
        self.served = 0

    def parse(self, words):
        name = words[0]
        if name not in FAULTS:
            return None, f"unknown fault '{name}' (one of {', '.join(FAULTS)})"
        if name == "wrong-tid" and self.mode != "tcp":
            return None, "wrong-tid needs MBAP (tcp mode)"
        if name == "bad-crc" and self.mode != "rtu-tcp":
            return None, "bad-crc needs RTU (rtu-tcp mode)"
        param = DEFAULT_PARAM.get(name, 0)
        if len(words) > 1:
            try:
                param = int(words[1], 0)
            except ValueError:
                return None, f"parameter '{words[1]}' of {name} is not a number"
        return (name, param), None

    def take(self):
        if self.once is not None:
            fault, self.once = self.once, None
            return fault
        return self.standing


class Registers:
    def __init__(self):
        self.holding = [holding_register(a) for a in range(TABLE_SIZE)]


def answer_pdu(pdu, registers):
    """The correct response PDU to a request PDU (Application Protocol V1.1b3, 6.3, 6.4, 6.6, 6.12)."""
    function = pdu[0]
    if function in (0x03, 0x04) and len(pdu) == 5:
        start, quantity = struct.unpack(">HH", pdu[1:5])
        if not 1 <= quantity <= 125:
            return bytes([function | 0x80, 0x03])
        if start + quantity > TABLE_SIZE:
            return bytes([function | 0x80, 0x02])
        if function == 0x03:
            values = registers.holding[start:start + quantity]
        else:
            values = [input_register(a) for a in range(start, start + quantity)]
        return bytes([function, 2 * quantity]) + struct.pack(f">{quantity}H", *values)
    if function == 0x06 and len(pdu) == 5:
        address, value = struct.unpack(">HH", pdu[1:5])
        if address >= TABLE_SIZE:
            return bytes([0x86, 0x02])
        registers.holding[address] = value
        return bytes(pdu)
    if function == 0x10 and len(pdu) >= 6:
        start, quantity, count = struct.unpack(">HHB", pdu[1:6])
        if not 1 <= quantity <= 123 or count != 2 * quantity or len(pdu) != 6 + count:
            return bytes([0x90, 0x03])
        if start + quantity > TABLE_SIZE:
            return bytes([0x90, 0x02])
        registers.holding[start:start + quantity] = struct.unpack(f">{quantity}H", pdu[6:])
        return bytes(pdu[:5])
    return bytes([function | 0x80, 0x01])


def rtu_request_length(buffer):
    """How long the RTU request at the buffer's start is, or 0 while unknown."""
    if len(buffer) < 2:
        return 0
    function = buffer[1]
    if function in (0x01, 0x02, 0x03, 0x04, 0x05, 0x06):
        return 8
    if function in (0x0F, 0x10):
        return 9 + buffer[6] if len(buffer) >= 7 else 0
    return len(buffer)  # unknown code: take what came (one request per write on a test link)


class Connection(asyncio.Protocol):
    def __init__(self, server):
        self.server = server
        self.buffer = b""
        self.queue = asyncio.Queue()
        self.transport = None
        self.worker = None

    def connection_made(self, transport):
        self.transport = transport
        self.server.connections.add(self)
        if self.server.dead:
            transport.close()
        self.worker = asyncio.create_task(self.work())

    def connection_lost(self, exc):
        self.server.connections.discard(self)
        if self.worker is not None:
            self.worker.cancel()

    def data_received(self, data):
        self.buffer += data
        while True:
            frame = self.take_frame()
            if frame is None:
                break
            self.queue.put_nowait(frame)

    def take_frame(self):
        if self.server.mode == "tcp":
            if len(self.buffer) < 7:
                return None
            length = struct.unpack(">H", self.buffer[4:6])[0]
            if len(self.buffer) < 6 + length:
                return None
            frame, self.buffer = self.buffer[:6 + length], self.buffer[6 + length:]
            return frame
        size = rtu_request_length(self.buffer)
        if size == 0 or len(self.buffer) < size:
            return None
        frame, self.buffer = self.buffer[:size], self.buffer[size:]
        if len(frame) < 4 or crc16(frame[:-2]) != frame[-2:]:
            self.buffer = b""  # lost synchronisation: start again with the next write
            return None
        return frame

    async def work(self):
        while True:
            frame = await self.queue.get()
            await self.serve(frame)

    def encode(self, tid, unit, pdu):
        if self.server.mode == "tcp":
            return struct.pack(">HHHB", tid, 0, len(pdu) + 1, unit) + pdu
        body = bytes([unit]) + pdu
        return body + crc16(body)

    async def serve(self, frame):
        if self.server.mode == "tcp":
            tid, protocol, _, unit = struct.unpack(">HHHB", frame[:7])
            pdu = frame[7:]
            if protocol != 0:
                return
        else:
            tid, unit, pdu = 0, frame[0], frame[1:-2]
        faults = self.server.faults
        faults.served += 1
        number = faults.served
        if number in self.server.drop_at or number == self.server.die_at:
            died = number == self.server.die_at
            say(f"SERVED {number} {'die' if died else 'drop'}")
            self.transport.close()
            if died:
                self.server.die()
            return
        if faults.standing[0] == "echo" and faults.once is None:
            self.transport.write(frame)
            say(f"SERVED {number} echo")
            return
        if unit != self.server.unit:
            say(f"SERVED {number} ignored-unit")  # an armed fault waits for a request it may answer
            return
        name, param = faults.take()
        response = answer_pdu(pdu, self.server.registers)
        if name == "exception":
            response = bytes([pdu[0] | 0x80, param & 0xFF])
        elif name == "short" and response[0] in (0x03, 0x04) and response[1] >= 4:
            response = bytes([response[0], response[1] - 2]) + response[2:-2]
        elif name == "wrong-function":
            other = {0x03: 0x04, 0x04: 0x03}.get(response[0] & 0x7F, 0x03)
            response = bytes([other]) + response[1:]
        if name == "wrong-tid":
            tid = (tid + 1) & 0xFFFF
        if name == "wrong-unit":
            unit = (unit + 1) & 0xFF
        adu = self.encode(tid, unit, response)
        if name == "bad-crc":
            adu = adu[:-2] + bytes(b ^ 0xFF for b in adu[-2:])
        write = self.transport.write
        if name == "silent":
            pass
        elif name == "close":
            write(adu[: max(1, len(adu) // 2)])
            # Well under the 50 ms an RTU-over-TCP client may take as the end of a frame: the
            # close must come mid-frame, not after a silence that already ended the answer.
            await asyncio.sleep(0.01)
            say(f"SERVED {number} {name}")  # closing cancels this task: report first
            self.transport.close()
            return
        elif name == "trickle":
            for i in range(len(adu)):
                write(adu[i:i + 1])
                await asyncio.sleep(param / 1000.0)
        elif name == "garbage":
            write((GARBAGE * (param // len(GARBAGE) + 1))[:param] + adu)
        elif name == "twice":
            write(adu + adu)
        elif name == "delay":
            await asyncio.sleep(param / 1000.0)
            write(adu)
        else:
            write(adu)
        say(f"SERVED {number} {name}")


class Server:
    def __init__(self, mode, unit, standing):
        self.mode = mode
        self.unit = unit
        self.faults = Faults(mode, ("none", 0))
        self.registers = Registers()
        self.drop_at = set()
        self.die_at = 0
        self.dead = False
        self.listener = None
        self.connections = set()
        if standing:
            words = standing.replace("=", " ").split()
            fault, error = self.faults.parse(words)
            if error:
                raise SystemExit(f"fault_server.py: --fault: {error}")
            self.faults.standing = fault

    def die(self):
        self.dead = True
        if self.listener is not None:
            self.listener.close()
        for connection in list(self.connections):
            connection.transport.close()

    def command(self, line):
        words = line.split()
        if not words:
            return
        if words[0] not in ("next", "always") or len(words) < 2:
            say(f"ERR expected 'next NAME [PARAM]' or 'always NAME [PARAM]', got '{line.strip()}'")
            return
        fault, error = self.faults.parse(words[1:])
        if error:
            say(f"ERR {error}")
            return
        if words[0] == "next":
            self.faults.once = fault
        else:
            self.faults.standing = fault
        say(f"OK {words[0]} {fault[0]} {fault[1]}")


async def main_async(args):
    loop = asyncio.get_running_loop()
    server = Server(args.mode, args.unit, args.fault)
    server.drop_at = {int(n) for n in args.drop_at.split(",") if n} if args.drop_at else set()
    server.die_at = args.die_at
    listener = await loop.create_server(lambda: Connection(server), args.host, args.port)
    server.listener = listener
    say(f"LISTENING {args.host}:{listener.sockets[0].getsockname()[1]}")

    done = asyncio.Event()
    loop.call_later(args.lifetime, done.set)
    reader = asyncio.StreamReader()
    await loop.connect_read_pipe(lambda: asyncio.StreamReaderProtocol(reader), sys.stdin)

    async def commands():
        while True:
            line = await reader.readline()
            if not line:
                break  # standard input closed: the test is gone
            server.command(line.decode(errors="replace"))
        done.set()

    task = asyncio.create_task(commands())
    await done.wait()
    task.cancel()
    listener.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["tcp", "rtu-tcp"])
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=0)
    parser.add_argument("--unit", type=int, default=1)
    parser.add_argument("--fault", help="fault for every request, NAME or NAME=PARAM")
    parser.add_argument("--lifetime", type=float, default=900.0)
    parser.add_argument("--drop-at", help="requests (1, 2...) whose connection is closed instead of answered")
    parser.add_argument("--die-at", type=int, default=0, help="the request at which the device dies (port closed)")
    args = parser.parse_args()
    try:
        asyncio.run(main_async(args))
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
