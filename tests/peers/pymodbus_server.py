#!/usr/bin/python3
"""A pymodbus 3.0 server for mbscope's integration tests.

Run with Debian's /usr/bin/python3 (python3-pymodbus 3.0). Modes:

  tcp        MBAP over TCP                      (mbscope target tcp://127.0.0.1:PORT)
  udp        MBAP, one frame per UDP datagram   (udp://127.0.0.1:PORT)
  rtu-tcp    RTU frames over a TCP stream       (rtu-tcp://127.0.0.1:PORT), as serial device servers do
  ascii-tcp  ASCII frames over a TCP stream     (ascii-tcp://127.0.0.1:PORT)
  rtu        RTU on a serial device or pty      (--device /dev/pts/N)
  ascii      ASCII on a serial device or pty    (--device /dev/pts/N)

Network modes bind 127.0.0.1 on --port (0, the default, lets the system choose) and print
"LISTENING 127.0.0.1:PORT" on stdout once the socket is bound; serial modes print
"LISTENING /dev/pts/N" once the device is open. Tests wait for that line and never guess ports.

The data map is the one in peer_datamap.h (keep both in step): PEER_TABLE_SIZE items per table;
coil(a) = a % 3 == 0, discrete input(a) = a % 2 == 1, holding register(a) = 1000 + 3a, input
register(a) = 40000 + 2a. Only unit --unit (default 1; a comma-separated list gives several units,
each with the same map) exists: pymodbus ignores requests for any other unit (no answer, on
every framing).
Serial modes (and rtu-tcp) with --broadcast execute unit-0 requests on the unit without answering.

Device identification (2B/0E) answers the objects printed by IDENTITY below. The process exits when its
standard input closes (the test that started it died) or after --lifetime seconds, so no peer outlives
its test.
"""

import argparse
import asyncio
import logging
import os
import sys
import threading

from pymodbus.datastore import (
    ModbusSequentialDataBlock,
    ModbusServerContext,
    ModbusSlaveContext,
)
from pymodbus.device import ModbusDeviceIdentification
from pymodbus.framer.ascii_framer import ModbusAsciiFramer
from pymodbus.framer.rtu_framer import ModbusRtuFramer
from pymodbus.framer.socket_framer import ModbusSocketFramer
from pymodbus.server.async_io import (
    ModbusSerialServer,
    ModbusTcpServer,
    ModbusUdpServer,
)

TABLE_SIZE = 10000  # PEER_TABLE_SIZE

IDENTITY = {
    "VendorName": "mbscope tests",
    "ProductCode": "PYPEER",
    "MajorMinorRevision": "3.0",
    "VendorUrl": "https://example.invalid/mbscope",
    "ProductName": "pymodbus test peer",
    "ModelName": "pymodbus_server.py",
    "UserApplicationName": "mbscope integration",
}


def coil(address):
    return address % 3 == 0


def discrete_input(address):
    return address % 2 == 1


def holding_register(address):
    return (1000 + 3 * address) & 0xFFFF


def input_register(address):
    return (40000 + 2 * address) & 0xFFFF


def make_context(unit):
    def block(fn):
        return ModbusSequentialDataBlock(0, [fn(a) for a in range(TABLE_SIZE)])

    # zero_mode: PDU address a is item a (pymodbus otherwise shifts every address by one).
    slave = ModbusSlaveContext(
        co=block(lambda a: 1 if coil(a) else 0),
        di=block(lambda a: 1 if discrete_input(a) else 0),
        hr=block(holding_register),
        ir=block(input_register),
        zero_mode=True,
    )
    return ModbusServerContext(slaves={u: slave for u in unit}, single=False)


def announce(where):
    sys.stdout.write(f"LISTENING {where}\n")
    sys.stdout.flush()


def watch_stdin(loop, stop):
    """Stops the server when standard input reaches its end: the parent test is gone."""

    def run():
        try:
            while sys.stdin.buffer.read(4096):
                pass
        except (OSError, ValueError):
            pass
        loop.call_soon_threadsafe(stop.set)

    threading.Thread(target=run, daemon=True).start()


async def serve(args):
    loop = asyncio.get_running_loop()
    stop = asyncio.Event()
    if not args.no_stdin_watch:
        watch_stdin(loop, stop)
    loop.call_later(args.lifetime, stop.set)

    context = make_context(args.unit)
    identity = ModbusDeviceIdentification(info_name=IDENTITY)
    framers = {
        "tcp": ModbusSocketFramer,
        "udp": ModbusSocketFramer,
        "rtu-tcp": ModbusRtuFramer,
        "ascii-tcp": ModbusAsciiFramer,
        "rtu": ModbusRtuFramer,
        "ascii": ModbusAsciiFramer,
    }
    framer = framers[args.mode]
    # ignore_missing_slaves: no answer for other units on every framing (pymodbus otherwise answers
    # exception 0B on the serial framings and stays silent on MBAP).
    options = {"broadcast_enable": args.broadcast, "ignore_missing_slaves": True}

    if args.mode in ("tcp", "rtu-tcp", "ascii-tcp"):
        server = ModbusTcpServer(
            context, framer=framer, identity=identity, address=(args.host, args.port), **options
        )
        task = asyncio.create_task(server.serve_forever())
        await server.serving
        port = server.server.sockets[0].getsockname()[1]
        announce(f"{args.host}:{port}")
    elif args.mode == "udp":
        server = ModbusUdpServer(
            context, framer=framer, identity=identity, address=(args.host, args.port), **options
        )
        task = asyncio.create_task(server.serve_forever())
        await server.serving
        port = server.protocol.get_extra_info("sockname")[1]
        announce(f"{args.host}:{port}")
    else:
        if not args.device:
            print("pymodbus_server.py: --device is required for serial modes", file=sys.stderr)
            return 2
        server = ModbusSerialServer(
            context,
            framer=framer,
            identity=identity,
            port=args.device,
            baudrate=args.baud,
            bytesize=8,
            parity=args.parity,
            stopbits=1,
            **options,
        )
        await server.start()
        if server.transport is None:
            print(f"pymodbus_server.py: cannot open {args.device}", file=sys.stderr)
            return 2
        task = None
        announce(args.device)

    await stop.wait()
    await server.shutdown()
    if task is not None:
        task.cancel()
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["tcp", "udp", "rtu-tcp", "ascii-tcp", "rtu", "ascii"])
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=0)
    parser.add_argument("--device", help="serial device or pty for rtu and ascii")
    parser.add_argument("--baud", type=int, default=115200)
    parser.add_argument("--parity", default="N", choices=["N", "E", "O"])
    parser.add_argument("--unit", type=lambda text: [int(u) for u in text.split(",")], default=[1])
    parser.add_argument("--broadcast", action="store_true", help="execute unit 0 requests silently")
    parser.add_argument("--lifetime", type=float, default=900.0, help="exit after this many seconds")
    parser.add_argument("--no-stdin-watch", action="store_true", help="keep running when stdin closes")
    parser.add_argument("--debug", action="store_true", help="pymodbus debug log on stderr")
    args = parser.parse_args()

    # pymodbus.constants calls logging.basicConfig at import: set the root level instead.
    logging.getLogger().setLevel(logging.DEBUG if args.debug else logging.CRITICAL)
    try:
        code = asyncio.run(serve(args))
    except KeyboardInterrupt:
        code = 0
    sys.stdout.flush()
    # pymodbus may leave tasks behind on shutdown; do not wait for them.
    os._exit(code)


if __name__ == "__main__":
    main()
