#!/usr/bin/env python3
"""A Foxglove client that never reads (docs/foxglove.md, "Bounds"), for bench/foxglove_stall.sh.

  stalled_foxglove_client.py PORT idle|subscribe

Connects to ws://127.0.0.1:PORT with a 4 KiB receive buffer, does the WebSocket handshake
(subprotocol foxglove.websocket.v1); `subscribe` then reads up to the advertisement and
subscribes to every channel. After that it reads nothing until it is killed: the server's
writes to it stall, as for a frozen Foxglove app. Prints "stalled" once it is.
"""
import json
import socket
import struct
import sys
import time


def frame(opcode, payload):
    """a masked client frame (RFC 6455 5.2)"""
    mask = b"\x5a\x17\xc3\x29"
    n = len(payload)
    head = bytes([0x80 | opcode])
    if n < 126:
        head += bytes([0x80 | n])
    elif n < 65536:
        head += bytes([0x80 | 126]) + struct.pack(">H", n)
    else:
        head += bytes([0x80 | 127]) + struct.pack(">Q", n)
    return head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload))


def main():
    port, mode = int(sys.argv[1]), sys.argv[2]
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.connect(("127.0.0.1", port))
    s.sendall(("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\n"
               "Connection: Upgrade\r\nSec-WebSocket-Key: dG93c2ltIGJlbmNoIGNsaWVudA==\r\n"
               "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Protocol: foxglove.websocket.v1\r\n"
               "\r\n").encode())
    head = b""
    while not head.endswith(b"\r\n\r\n"):
        head += s.recv(1)
    if not head.startswith(b"HTTP/1.1 101"):
        sys.exit("handshake refused: " + head.decode(errors="replace"))
    if mode == "subscribe":
        buf = b""
        while True:
            while len(buf) < 10:
                buf += s.recv(65536)
            n, at = buf[1] & 127, 2
            if n == 126:
                n, at = struct.unpack(">H", buf[2:4])[0], 4
            elif n == 127:
                n, at = struct.unpack(">Q", buf[2:10])[0], 10
            while len(buf) < at + n:
                buf += s.recv(65536)
            opcode, payload, buf = buf[0] & 15, buf[at:at + n], buf[at + n:]
            if opcode == 1 and json.loads(payload).get("op") == "advertise":
                ids = [c["id"] for c in json.loads(payload)["channels"]]
                break
        subs = [{"id": i, "channelId": i} for i in ids]
        s.sendall(frame(1, json.dumps({"op": "subscribe", "subscriptions": subs}).encode()))
    print("stalled", flush=True)
    while True:
        time.sleep(3600)


if __name__ == "__main__":
    main()
