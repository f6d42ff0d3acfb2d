#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""tiny_uart.py: the UART traffic of the timing-annotated check's small design
(tb/postroute/sdf_tiny/sdf_tiny.v, tests/checks/postroute_sdf.sh), in the record format of
tb/postroute/postroute_replay_tb.v ("<cycle> <level>" at each change).

  tiny_uart.py txd <file>     writes the ftdi_txd record: BYTES, 8N1 at 25 cycles a bit, from
                              cycle 100, one every 650 cycles; prints the cycles it needs
  tiny_uart.py check <file>   decodes an ftdi_rxd record and compares its bytes with the design's
                              replies (sum += {b, b} * {b, ~b}; reply sum[23:16] ^ sum[15:8] ^
                              b: sdf_tiny's two sums are equal); exit 1 if they differ
"""
import sys

BYTES = [0x00, 0x5A, 0xFF, 0x13, 0x80, 0x7F]
DIV, START, GAP = 25, 100, 650


def write_txd(path):
    level, cyc = 1, START
    with open(path, "w") as f:
        for b in BYTES:
            for i, bit in enumerate([0] + [(b >> k) & 1 for k in range(8)] + [1]):
                if bit != level:
                    f.write(f"{cyc + DIV * i} {bit}\n")
                    level = bit
            cyc += GAP
    print(cyc + GAP)


def replies():
    s, out = 0, []
    for b in BYTES:
        s = (s + ((b << 8) | b) * ((b << 8) | (~b & 0xFF))) & 0xFFFFFFFF
        out.append(((s >> 16) ^ (s >> 8) ^ b) & 0xFF)
    return out


def decode(path):
    changes = [tuple(map(int, line.split())) for line in open(path)]
    last = changes[-1][0] + 10 * DIV

    def level(n):
        v = 1
        for c, lv in changes:
            if c > n:
                break
            v = lv
        return v
    got, n = [], 0
    while n < last:
        if level(n) == 0:
            got.append(sum(level(n + DIV * (i + 1) + DIV // 2) << i for i in range(8)))
            n += 10 * DIV
        else:
            n += 1
    return got


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("txd", "check"):
        sys.exit("usage: tiny_uart.py txd|check <file>")
    if sys.argv[1] == "txd":
        write_txd(sys.argv[2])
        return
    got, want = decode(sys.argv[2]), replies()
    if got != want:
        sys.exit(f"{sys.argv[2]}: replies {[hex(x) for x in got]}, expected {[hex(x) for x in want]}")
    print(f"{len(got)} replies as expected")


if __name__ == "__main__":
    main()
