#!/usr/bin/python3
"""A pymodbus client checking what mbscope's simulator serves (run with /usr/bin/python3).

    sim_client.py SCENARIO PORT [tcp|rtu-tcp]

Scenarios: rosrao (units 1 and 3 of the rosrao-gamma profile), conformance (unit 1 of the
conformance profile). Prints one "ok ..." line per check; exits 1 at the first "FAIL ..." line.
"""
import sys

from pymodbus.client import ModbusTcpClient
from pymodbus.transaction import ModbusRtuFramer, ModbusSocketFramer

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


def rosrao(client):
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


def conformance(client):
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


def main():
    scenario, port = sys.argv[1], int(sys.argv[2])
    framing = sys.argv[3] if len(sys.argv) > 3 else "tcp"
    framer = ModbusRtuFramer if framing == "rtu-tcp" else ModbusSocketFramer
    client = ModbusTcpClient("127.0.0.1", port=port, framer=framer, timeout=5, retries=0)
    if not client.connect():
        print(f"FAIL cannot connect to 127.0.0.1:{port}", flush=True)
        sys.exit(1)
    {"rosrao": rosrao, "conformance": conformance}[scenario](client)
    client.close()
    print("done", flush=True)


if __name__ == "__main__":
    main()
