#!/usr/bin/python3
"""A pymodbus client checking what mbscope's simulator serves (run with /usr/bin/python3).

    sim_client.py SCENARIO PORT [tcp|rtu-tcp|udp|rtu-udp]
    sim_client.py SCENARIO PORT tls --ca CA.pem --cert CLIENT.pem --key CLIENT.key
    sim_client.py SCENARIO DEVICE rtu|ascii        (a pty: 19200 8N1)

Scenarios: rosrao (units 1 and 3 of the rosrao-gamma profile), conformance (unit 1 of the
conformance profile). Prints one "ok ..." line per check; exits 1 at the first "FAIL ..." line.
tls is MODBUS/TCP Security: MBAP inside mutual TLS, the server checked against the CA.
"""
import argparse
import socket
import ssl
import sys

from pymodbus.client import ModbusSerialClient, ModbusTcpClient, ModbusTlsClient, ModbusUdpClient
from pymodbus.transaction import ModbusAsciiFramer, ModbusRtuFramer, ModbusSocketFramer

PUBLISHED = [1050, 0, 0, 0, 250, 1, 1000, 10000, 4, 4, 80, 800, 8000]


def check(what, got, expected):
    if got != expected:
        print(f"FAIL {what}: got {got}, expected {expected}", flush=True)
        sys.exit(1)
    print(f"ok {what}", flush=True)


def registers(client, address, count, unit):
    reply = client.read_holding_registers(address, count, slave=unit)
    if reply.isError():
        print(f"FAIL read {count} at {address:#06x} unit {unit}: {reply}", flush=True)
        sys.exit(1)
    return list(reply.registers)


def rosrao(client, framing):  # pylint: disable=unused-argument
    for unit in (1, 3):
        values = registers(client, 0x0079, 22, unit)
        check(f"unit {unit} published values at 0x0079", values[:13], PUBLISHED)
        check(f"unit {unit} results at 0x0087 are 0", values[14:], [0] * 8)
    # 06 then 03: the write sticks; 10 then 03.
    reply = client.write_register(0x007D, 300, slave=1)
    check("06 answered", reply.isError(), False)
    check("06 value read back", registers(client, 0x007D, 1, 1), [300])
    reply = client.write_registers(0x0087, [1, 2, 3], slave=3)
    check("10 answered", reply.isError(), False)
    check("10 values read back", registers(client, 0x0087, 3, 3), [1, 2, 3])
    check("unit 1 untouched by unit 3's write", registers(client, 0x0087, 3, 1), [0, 0, 0])
    # Function 04 is not in the profile's set: exception 01 (illegal function).
    reply = client.read_input_registers(0x0079, 1, slave=1)
    check("04 refused", reply.isError(), True)
    check("04 exception code", getattr(reply, "exception_code", None), 1)
    # Beyond the map: exception 02 (illegal data address).
    reply = client.read_holding_registers(0x0100, 1, slave=1)
    check("03 beyond the map refused", getattr(reply, "exception_code", None), 2)


def conformance(client, framing):
    reply = client.read_coils(0, 30, slave=1)
    check("01 coils", list(reply.bits[:30]), [a % 3 == 0 for a in range(30)])
    reply = client.read_discrete_inputs(0, 20, slave=1)
    check("02 discrete inputs", list(reply.bits[:20]), [a % 2 == 1 for a in range(20)])
    reply = client.read_input_registers(10, 20, slave=1)
    check("04 input registers", list(reply.registers), [40000 + 2 * a for a in range(10, 30)])
    check("03 holding registers", registers(client, 0, 50, 1), [1000 + 3 * a for a in range(50)])
    check("03 u32 at 204", registers(client, 204, 2, 1), [0x1234, 0x5678])
    reply = client.write_coil(1, True, slave=1)
    check("05 answered", reply.isError(), False)
    check("05 read back", client.read_coils(0, 3, slave=1).bits[:3], [True, True, False])
    reply = client.write_coils(10, [True, False, True], slave=1)
    check("0F answered", reply.isError(), False)
    check("0F read back", client.read_coils(10, 3, slave=1).bits[:3], [True, False, True])
    client.write_register(7, 4242, slave=1)
    client.write_registers(20, [7, 8, 9], slave=1)
    check("06/10 read back", registers(client, 7, 1, 1) + registers(client, 20, 3, 1), [4242, 7, 8, 9])
    reply = client.read_holding_registers(0, 126, slave=1)
    check("03 quantity 126 refused with 03", getattr(reply, "exception_code", None), 3)
    check("03 typed registers 200-217", registers(client, 200, 18, 1),
          [0x42F6, 0xE979, 0xE979, 0x42F6, 0x1234, 0x5678, 0xFFFF, 0xFFFE, 0xFF83, 11325,
           0x4009, 0x21FB, 0x5444, 0x2D18, 0x4D42, 0x5343, 0x4F50, 0x4520])
    reply = client.write_register(300, 1, slave=1)
    check("06 into the read-only block refused with 02", getattr(reply, "exception_code", None), 2)
    check("read-only block unchanged", registers(client, 300, 10, 1), [7] * 10)
    reply = client.read_exception_status(slave=1)
    check("07 exception status", getattr(reply, "status", None), 0x6D)
    # V1.1b3 6.16's example: 0x12 AND 0xF2 OR (0x25 AND NOT 0xF2) = 0x17; 17 writes, then reads.
    # pymodbus 3.0's RTU and ASCII framers cannot wait for these answers whole: MBAP framings
    # only (libmodbus_conformance.c checks 16 and 17 over RTU).
    if framing in ("tcp", "udp", "tls"):
        client.write_register(4, 0x12, slave=1)
        reply = client.mask_write_register(address=4, and_mask=0xF2, or_mask=0x25, slave=1)
        check("16 answered", reply.isError(), False)
        check("16 read back", registers(client, 4, 1, 1), [0x17])
        reply = client.readwrite_registers(read_address=38, read_count=6, write_address=40,
                                           write_registers=[111, 222, 333], slave=1)
        check("17 reads after it writes", list(getattr(reply, "registers", [])),
              [1000 + 3 * 38, 1000 + 3 * 39, 111, 222, 333, 1000 + 3 * 43])
    check("unit 2 holding registers", registers(client, 0, 10, 2), [2000 + a for a in range(10)])
    reply = client.read_coils(0, 1, slave=2)
    check("unit 2 refuses 01 with 01", getattr(reply, "exception_code", None), 1)


class BlockingTlsClient(ModbusTlsClient):
    """pymodbus 3.0's TLS client reads after select() on the socket, which does not see bytes
    already decrypted into the TLS layer's buffer: the rest of an answer waits for the timeout.
    Blocking reads with the timeout instead."""

    def recv(self, size):
        self.socket.settimeout(self.params.timeout)
        data = b""
        try:
            while True:
                chunk = self.socket.recv(4096 if size is None else size - len(data))
                data += chunk
                if not chunk or size is None or len(data) >= size:
                    return data
        except (socket.timeout, ssl.SSLError):
            return data


def connect(args):
    """A connected pymodbus client for the framing, or exits 1 saying why."""
    framing = args.framing
    if framing in ("rtu", "ascii"):
        framer = ModbusRtuFramer if framing == "rtu" else ModbusAsciiFramer
        client = ModbusSerialClient(args.target, framer=framer, baudrate=19200, bytesize=8, parity="N",
                                    stopbits=1, timeout=5, retries=0)
        where = args.target
    else:
        port = int(args.target)
        where = f"127.0.0.1:{port}"
        framer = ModbusRtuFramer if framing.startswith("rtu-") else ModbusSocketFramer
        if framing in ("udp", "rtu-udp"):
            client = ModbusUdpClient("127.0.0.1", port=port, framer=framer, timeout=5, retries=0)
        elif framing == "tls":
            context = ssl.create_default_context(ssl.Purpose.SERVER_AUTH, cafile=args.ca)
            context.load_cert_chain(certfile=args.cert, keyfile=args.key)
            # The server's certificate names IP:127.0.0.1; MBAP, not pymodbus's header-less TLS framer.
            client = BlockingTlsClient("127.0.0.1", port=port, framer=ModbusSocketFramer, sslctx=context,
                                     timeout=5, retries=0)
        else:
            client = ModbusTcpClient("127.0.0.1", port=port, framer=framer, timeout=5, retries=0)
    if not client.connect():
        print(f"FAIL cannot connect to {where} ({framing})", flush=True)
        sys.exit(1)
    return client


def main():
    parser = argparse.ArgumentParser(description="pymodbus checks against mbscope simulate")
    parser.add_argument("scenario", choices=["rosrao", "conformance"])
    parser.add_argument("target", help="port, or the device of a serial framing")
    parser.add_argument("framing", nargs="?", default="tcp",
                        choices=["tcp", "rtu-tcp", "udp", "rtu-udp", "tls", "rtu", "ascii"])
    parser.add_argument("--ca")
    parser.add_argument("--cert")
    parser.add_argument("--key")
    args = parser.parse_args()
    if args.framing == "tls" and not (args.ca and args.cert and args.key):
        parser.error("tls needs --ca, --cert and --key")
    client = connect(args)
    {"rosrao": rosrao, "conformance": conformance}[args.scenario](client, args.framing)
    client.close()
    print("done", flush=True)


if __name__ == "__main__":
    main()
