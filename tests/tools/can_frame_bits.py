#!/usr/bin/env python3
"""Independent CAN / CAN FD frame length calculator (ISO 11898-1:2015 layout).

Written apart from drivers/virtual/can_bits.cpp to check it: it builds the frame's
actually transmitted bit sequence (with stuff bits inserted, CRCs computed) and counts it.

Usage:
  can_frame_bits.py --check-exe EXE   runs EXE (tests/tools/can_bits_dump) and checks its output
  can_frame_bits.py --check DUMP   DUMP lines: "<ext> <fd> <brs> <rtr> <id hex> <data hex|-|R<dlc>> <nominal> <data> <stuff>"
                                   (as written by can_bits_dump); exits 1 on any mismatch.
  can_frame_bits.py EXT FD BRS RTR ID_HEX DATA_HEX   prints "nominal data stuff" for one frame.
"""
import subprocess
import sys

FD_LENGTHS = [0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64]


def crc(bits, width, poly, init):
    reg, top, mask = init, 1 << (width - 1), (1 << width) - 1
    for b in bits:
        feedback = bool(reg & top) != bool(b)
        reg = (reg << 1) & mask
        if feedback:
            reg ^= poly
    return reg


def as_bits(value, count):
    return [(value >> i) & 1 for i in range(count - 1, -1, -1)]


def dynamic_stuff(bits, stuff_after_last):
    """Returns the stuffed sequence as (bit, is_stuff, source_index) triples."""
    out, run, prev = [], 0, None
    for i, b in enumerate(bits):
        out.append((b, False, i))
        run = run + 1 if b == prev else 1
        prev = b
        if run == 5 and (stuff_after_last or i + 1 < len(bits)):
            out.append((1 - b, True, i))
            prev, run = 1 - b, 1
    return out


def frame_bits(ext, fd, brs, rtr, ident, data):
    dlc = FD_LENGTHS.index(len(data)) if fd else len(data)
    bits = [0]  # SOF
    if ext:
        bits += as_bits(ident >> 18, 11) + [1, 1] + as_bits(ident & 0x3FFFF, 18)
        bits += [0, 1, 0] if fd else [int(rtr), 0, 0]
    else:
        bits += as_bits(ident, 11)
        bits += [0, 0, 1, 0] if fd else [int(rtr), 0, 0]
    brs_index = len(bits)
    if fd:
        bits += [int(brs), 0]  # BRS, ESI (0)
    bits += as_bits(dlc, 4)
    if not rtr:
        for byte in data:
            bits += as_bits(byte, 8)
    tail = 1 + 1 + 1 + 7 + 3
    if not fd:
        bits += as_bits(crc(bits, 15, 0x4599, 0), 15)
        stuffed = dynamic_stuff(bits, True)
        stuff = sum(1 for s in stuffed if s[1])
        return len(stuffed) + tail, 0, stuff
    stuffed = dynamic_stuff(bits, False)
    dyn = sum(1 for s in stuffed if s[1])
    gray = dyn % 8 ^ (dyn % 8 >> 1)
    count_field = as_bits(gray, 3) + [bin(gray).count("1") % 2]
    width, poly = (17, 0x1685B) if len(data) <= 16 else (21, 0x102899)
    crc_value = crc([s[0] for s in stuffed] + count_field, width, poly, 1 << (width - 1))
    fixed_region = count_field + as_bits(crc_value, width)
    fixed = []
    prev = stuffed[-1][0]
    for i, b in enumerate(fixed_region):
        if i % 4 == 0:
            fixed.append(1 - prev)  # fixed stuff bit: complement of the bit before it
        fixed.append(b)
        prev = b
    n_fixed = len(fixed) - len(fixed_region)
    if not brs:
        return len(stuffed) + len(fixed) + tail, 0, dyn + n_fixed
    nominal_part = sum(1 for s in stuffed if s[2] < brs_index or (s[2] == brs_index and not s[1]))
    data_part = len(stuffed) - nominal_part + len(fixed)
    return nominal_part + tail, data_part, dyn + n_fixed


def main(argv):
    if len(argv) == 3 and argv[1] in ("--check", "--check-exe"):
        bad = 0
        if argv[1] == "--check-exe":
            text = subprocess.run([argv[2]], check=True, capture_output=True, text=True).stdout
        else:
            text = open(argv[2]).read()
        lines = text.split("\n")
        checked = 0
        for line in lines:
            if not line.strip():
                continue
            f = line.split()
            if f[5].startswith("R"):
                data = bytes(int(f[5][1:]))  # remote frame: the DLC only, no data sent
            else:
                data = b"" if f[5] == "-" else bytes.fromhex(f[5])
            want = tuple(int(x) for x in f[6:9])
            got = frame_bits(f[0] == "1", f[1] == "1", f[2] == "1", f[3] == "1", int(f[4], 16), data)
            checked += 1
            if got != want:
                bad += 1
                print(f"mismatch: {line} -> python {got}")
        print(f"{checked - bad} passed, {bad} failed")
        return 1 if bad or checked == 0 else 0
    if len(argv) == 7:
        data = b"" if argv[6] == "-" else bytes.fromhex(argv[6])
        print(*frame_bits(argv[1] == "1", argv[2] == "1", argv[3] == "1", argv[4] == "1", int(argv[5], 16), data))
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
