#!/usr/bin/python3
"""A simulated RS485 bus for mbscope's monitor tests: one master, one slave, one listener.

  bus_harness.py [--flip N,N...] [--drop N,N...] [--quiet-ms 3] [--lifetime S]
                 [--links PREFIX] [--ignore-stdin]

Makes three pseudo-terminals and prints their device paths in one line on stdout:

  LISTENING master=/dev/pts/A slave=/dev/pts/B monitor=/dev/pts/C

The master (mbpoll, pymodbus, mbscope poll) opens the first, the slave (mbscope simulate) the
second, the monitor under test the third. Every byte the master writes is relayed to the slave and
every byte the slave writes to the master, and each is copied, in the order relayed, to the
monitor's pty, as an RS485 transceiver hears the line. The monitor's pty is output-only: whatever
the monitor writes is counted (and never relayed), so a test can check that it wrote nothing.

Noise is applied on the line, so that master, slave and monitor all see the same damaged bytes.
The slave's bytes are held until the line has been quiet for --quiet-ms (an answer is one burst),
then an answer is counted (1, 2, 3...) and:
  --flip N,...   flips bit 0 of the last data byte (the byte before the CRC) of those answers:
                 the length and the keys stay, the CRC no longer matches;
  --drop N,...   drops the last byte of those answers: a frame cut short.

--links PREFIX also names the ptys PREFIX-master, PREFIX-slave and PREFIX-monitor (symbolic links,
removed at the end), for examples that must run as written. A line "stats" on standard input is answered by
  STATS requests=R answers=A flipped=F dropped=D monitor_wrote=W
(requests: bursts from the master, apart by --quiet-ms). The process exits when its standard input
closes (the test that started it died) or after --lifetime seconds; with --ignore-stdin (run in
the background from a shell) only after --lifetime.
"""

import argparse
import os
import select
import sys
import time
import tty


def numbers(text):
    return {int(item) for item in text.split(",") if item.strip()} if text else set()


def open_pty():
    """A pty whose device stays open here, raw, so that peers may open and close it at will."""
    controller, device = os.openpty()
    tty.setraw(device)
    os.set_blocking(controller, False)
    return controller, device, os.ttyname(device)


def write_all(fd, data):
    while data:
        try:
            written = os.write(fd, data)
        except BlockingIOError:
            select.select([], [fd], [], 0.1)
            continue
        data = data[written:]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flip", default="", help="answers (1-based) whose last data byte gets a bit flipped")
    parser.add_argument("--drop", default="", help="answers (1-based) whose last byte is dropped")
    parser.add_argument("--quiet-ms", type=float, default=3.0, help="silence that ends the slave's answer")
    parser.add_argument("--lifetime", type=float, default=300.0)
    parser.add_argument("--links", default="", help="also name the ptys PREFIX-master, PREFIX-slave, PREFIX-monitor")
    parser.add_argument("--ignore-stdin", action="store_true", help="run until --lifetime, whatever standard input does")
    args = parser.parse_args()

    master, master_device, master_path = open_pty()
    slave, slave_device, slave_path = open_pty()
    monitor, monitor_device, monitor_path = open_pty()
    links = []
    if args.links:
        for role, path in (("master", master_path), ("slave", slave_path), ("monitor", monitor_path)):
            link = f"{args.links}-{role}"
            if os.path.islink(link):
                os.unlink(link)
            os.symlink(path, link)
            links.append(link)
    print(f"LISTENING master={master_path} slave={slave_path} monitor={monitor_path}", flush=True)
    try:
        return relay(args, master, slave, monitor)
    finally:
        for link in links:
            if os.path.islink(link):
                os.unlink(link)


def relay(args, master, slave, monitor):
    flip = numbers(args.flip)
    drop = numbers(args.drop)

    counts = {"requests": 0, "answers": 0, "flipped": 0, "dropped": 0, "monitor_wrote": 0}
    answer = bytearray()
    answer_at = 0.0
    master_at = 0.0
    deadline = time.monotonic() + args.lifetime
    stdin = sys.stdin.fileno()
    watched = [master, slave, monitor] + ([] if args.ignore_stdin else [stdin])
    control = b""

    def release_answer():
        nonlocal answer
        counts["answers"] += 1
        data = bytearray(answer)
        answer = bytearray()
        number = counts["answers"]
        if number in flip and len(data) >= 3:
            data[-3] ^= 0x01
            counts["flipped"] += 1
        if number in drop and len(data) >= 1:
            del data[-1]
            counts["dropped"] += 1
        write_all(master, bytes(data))
        write_all(monitor, bytes(data))

    while time.monotonic() < deadline:
        timeout = None
        if answer:
            timeout = max(0.0, answer_at + args.quiet_ms / 1000.0 - time.monotonic())
        readable, _, _ = select.select(watched, [], [], timeout if timeout is not None else 0.5)
        if answer and time.monotonic() >= answer_at + args.quiet_ms / 1000.0 and slave not in readable:
            release_answer()
        for fd in readable:
            if fd == stdin:
                chunk = os.read(stdin, 4096)
                if not chunk:
                    return 0
                control += chunk
                while b"\n" in control:
                    line, control = control.split(b"\n", 1)
                    if line.strip() == b"stats":
                        print("STATS " + " ".join(f"{k}={v}" for k, v in counts.items()), flush=True)
                continue
            try:
                chunk = os.read(fd, 4096)
            except (BlockingIOError, OSError):
                # EIO: nobody has the other end open just now (a master between two runs).
                continue
            if not chunk:
                continue
            if fd == master:
                if answer:
                    release_answer()  # the master speaks: the slave's turn is over
                now = time.monotonic()
                if now - master_at > args.quiet_ms / 1000.0:
                    counts["requests"] += 1
                master_at = now
                write_all(slave, chunk)
                write_all(monitor, chunk)
            elif fd == slave:
                master_at = 0.0
                answer += chunk
                answer_at = time.monotonic()
            else:
                counts["monitor_wrote"] += len(chunk)
    return 0


if __name__ == "__main__":
    sys.exit(main())
