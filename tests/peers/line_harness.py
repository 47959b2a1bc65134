#!/usr/bin/python3
"""A serial line with settings, for mbscope scan --line: two pseudo-terminals relayed to each other
only when the client's baud rate and stop bits are the device's.

  line_harness.py --baud 19200 --stop 1 [--links PREFIX] [--lifetime S] [--ignore-stdin]

Prints "LISTENING client=/dev/pts/A device=/dev/pts/B" on stdout. The device (mbscope simulate on
rtu://B) is taken to run at --baud and --stop; the harness reads the line settings the client set
on its pty (tcgetattr on the pty's master side gives the slave's baud rate and CSTOPB) before it
relays each chunk. When they differ, the bytes are garbled in both directions as a UART at another
rate garbles them (every byte inverted, every other byte lost), so the device sees no valid frame
and the client sees no valid answer. A pty carries no parity bit (Linux clears PARENB on ptys),
so parity cannot be emulated: every parity passes at the right rate.

--links PREFIX also names the ptys PREFIX-client and PREFIX-device (symbolic links, removed at the
end), for examples that must run as written. The process exits when its standard input closes (the
test that started it died) or after --lifetime seconds; with --ignore-stdin only after --lifetime.
"""

import argparse
import os
import pty
import select
import sys
import termios
import time
import tty

SPEEDS = {getattr(termios, name): int(name[1:]) for name in dir(termios)
          if name.startswith("B") and name[1:].isdigit()}


def open_pty():
    master, slave = pty.openpty()
    tty.setraw(slave)
    return master, slave, os.ttyname(slave)


def line_of(master):
    attrs = termios.tcgetattr(master)
    return SPEEDS.get(attrs[4], 0), 2 if attrs[2] & termios.CSTOPB else 1


def garble(data):
    return bytes(b ^ 0xFF for i, b in enumerate(data) if i % 2 == 0)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--baud", type=int, required=True)
    parser.add_argument("--stop", type=int, default=1, choices=[1, 2])
    parser.add_argument("--links")
    parser.add_argument("--lifetime", type=float, default=900.0)
    parser.add_argument("--ignore-stdin", action="store_true")
    args = parser.parse_args()

    client_m, client_s, client_name = open_pty()
    device_m, device_s, device_name = open_pty()
    links = []
    if args.links:
        for suffix, target in (("client", client_name), ("device", device_name)):
            path = f"{args.links}-{suffix}"
            if os.path.islink(path):
                os.unlink(path)
            os.symlink(target, path)
            links.append(path)
    sys.stdout.write(f"LISTENING client={client_name} device={device_name}\n")
    sys.stdout.flush()

    watched = [client_m, device_m]
    if not args.ignore_stdin:
        watched.append(sys.stdin.fileno())
    end = time.monotonic() + args.lifetime
    try:
        while time.monotonic() < end:
            ready, _, _ = select.select(watched, [], [], 0.2)
            for fd in ready:
                if fd == sys.stdin.fileno():
                    if not os.read(fd, 4096):
                        return
                    continue
                try:
                    data = os.read(fd, 4096)
                except OSError:
                    continue  # the other side is not open yet (EIO)
                if not data:
                    continue
                if line_of(client_m) != (args.baud, args.stop):
                    data = garble(data)
                os.write(device_m if fd == client_m else client_m, data)
    finally:
        for path in links:
            if os.path.islink(path):
                os.unlink(path)


if __name__ == "__main__":
    main()
