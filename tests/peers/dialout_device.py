#!/usr/bin/python3
"""A device that dials out to its master, as cellular data units and some gateways do (they
connect to a server and then expect Modbus requests on that connection), for mbscope's reverse
connection tests (--target URL?mode=listen).

  dialout_device.py MASTER_PORT SERVER_PORT [--framing rtu|tcp] [--answers N] [--connections C]
                    [--lifetime S] [--hang-up-on-request]

Connects to 127.0.0.1:MASTER_PORT, trying again every 50 ms until something listens there, and
relays each request that comes on that connection to the Modbus server on 127.0.0.1:SERVER_PORT
(mbscope simulate, say), and its answer back. Frames are cut by their own lengths: RTU (MODBUS over
Serial Line V1.02) or MBAP (Messaging on TCP/IP V1.0b). After N answers on one connection (0: no
limit) it closes that connection and dials again, C connections in all, then exits. With
--hang-up-on-request it first waits for the next request and closes instead of answering it: the
master then knows which request met the hang-up (closing between requests races the master's next
request, which may or may not see the close before it is sent).

Prints "CONNECTED k" when connection k is up, "ANSWERED k n" after the n-th answer on it, and
"CLOSED k" when it ends (by us or by the master). Exits when its standard input closes, or after
--lifetime seconds (default 120).
"""

import argparse
import socket
import sys
import threading
import time
import os


def read_exact(sock, n):
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            raise ConnectionError("closed")
        data += chunk
    return data


def read_rtu_request(sock):
    head = read_exact(sock, 2)
    fc = head[1]
    if fc in (15, 16):
        rest = read_exact(sock, 5)
        return head + rest + read_exact(sock, rest[4] + 2)
    return head + read_exact(sock, 6)


def read_rtu_answer(sock):
    head = read_exact(sock, 3)
    fc = head[1]
    if fc & 0x80:
        return head + read_exact(sock, 2)
    if fc in (1, 2, 3, 4):
        return head + read_exact(sock, head[2] + 2)
    return head + read_exact(sock, 5)


def read_mbap(sock):
    head = read_exact(sock, 6)
    length = (head[4] << 8) | head[5]
    return head + read_exact(sock, length)


def dial(port):
    while True:
        try:
            return socket.create_connection(("127.0.0.1", port))
        except OSError:
            time.sleep(0.05)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("master_port", type=int)
    parser.add_argument("server_port", type=int)
    parser.add_argument("--framing", choices=("rtu", "tcp"), default="rtu")
    parser.add_argument("--answers", type=int, default=0)
    parser.add_argument("--connections", type=int, default=1)
    parser.add_argument("--lifetime", type=float, default=120)
    parser.add_argument("--hang-up-on-request", action="store_true")
    args = parser.parse_args()

    def watch_stdin():
        sys.stdin.read()
        os._exit(0)

    threading.Thread(target=watch_stdin, daemon=True).start()
    threading.Timer(args.lifetime, lambda: os._exit(3)).start()

    read_request = read_rtu_request if args.framing == "rtu" else read_mbap
    read_answer = read_rtu_answer if args.framing == "rtu" else read_mbap
    server = socket.create_connection(("127.0.0.1", args.server_port))
    for k in range(1, args.connections + 1):
        master = dial(args.master_port)
        print("CONNECTED %d" % k, flush=True)
        answered = 0
        try:
            while args.answers == 0 or answered < args.answers:
                request = read_request(master)
                server.sendall(request)
                master.sendall(read_answer(server))
                answered += 1
                print("ANSWERED %d %d" % (k, answered), flush=True)
            if args.hang_up_on_request:
                read_request(master)
                print("DROPPED %d" % k, flush=True)
        except (ConnectionError, OSError):
            pass
        master.close()
        print("CLOSED %d" % k, flush=True)
    os._exit(0)


if __name__ == "__main__":
    main()
