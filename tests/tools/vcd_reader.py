#!/usr/bin/env python3
"""A small, independent VCD reader (IEEE 1364-2005 section 18) used to check hilrig's writer.

It knows nothing of hilrig's code: it tokenizes the file, follows $scope/$upscope to build
dotted names, reads $var declarations, and collects every value change (scalar 0/1/x/z,
vectors b..., reals r...) with its time, checking the file's rules on the way (times
strictly ascending, identifiers declared, vector widths respected, $dumpvars at the start).

  vcd_reader.py FILE.vcd                     prints "<time> <name> <value>" per change
  vcd_reader.py --check-fixture EXE          runs EXE DIR (tests/tools/vcd_fixture), which writes
                                             DIR/trace.vcd, DIR/stream.vcd and DIR/expected.txt,
                                             and checks both VCDs read back as expected.txt says
"""
import os
import subprocess
import sys
import tempfile


class VcdError(Exception):
    pass


def read_vcd(text):
    tokens = text.split()
    pos = 0
    scopes = []
    vars_by_id = {}  # id -> list of (name, kind, width)
    timescale = None
    changes = []  # (time, name, value)
    time = None
    in_dumpvars = False

    def section():
        nonlocal pos
        body = []
        while tokens[pos] != "$end":
            body.append(tokens[pos])
            pos += 1
        pos += 1
        return body

    # Header
    while True:
        if pos >= len(tokens):
            raise VcdError("no $enddefinitions")
        tok = tokens[pos]
        pos += 1
        if tok in ("$date", "$version", "$comment"):
            section()
        elif tok == "$timescale":
            timescale = "".join(section())
        elif tok == "$scope":
            body = section()
            if len(body) != 2:
                raise VcdError(f"bad $scope {body}")
            scopes.append(body[1])
        elif tok == "$upscope":
            section()
            if not scopes:
                raise VcdError("$upscope without $scope")
            scopes.pop()
        elif tok == "$var":
            body = section()
            if len(body) not in (4, 5):
                raise VcdError(f"bad $var {body}")
            kind, width, ident, ref = body[0], int(body[1]), body[2], body[3]
            name = ".".join(scopes + [ref])
            vars_by_id.setdefault(ident, []).append((name, kind, width))
        elif tok == "$enddefinitions":
            section()
            break
        else:
            raise VcdError(f"unexpected {tok} in header")
    if scopes:
        raise VcdError("unclosed $scope")
    if timescale != "1ns":
        raise VcdError(f"timescale {timescale}, expected 1ns")

    def record(ident, value):
        if time is None:
            raise VcdError("value change before the first #time")
        if ident not in vars_by_id:
            raise VcdError(f"undeclared identifier {ident}")
        for name, kind, width in vars_by_id[ident]:
            if kind == "real":
                if not value.startswith("r"):
                    raise VcdError(f"non-real value for {name}")
                changes.append((time, name, float(value[1:])))
            elif value.startswith("b"):
                bits = value[1:]
                if len(bits) > width or any(c not in "01xz" for c in bits):
                    raise VcdError(f"bad vector {value} for {name} ({width} bits)")
                changes.append((time, name, "x" if "x" in bits else int(bits, 2)))
            else:
                if width != 1:
                    raise VcdError(f"scalar change for {width}-bit {name}")
                changes.append((time, name, "x" if value in "xz" else int(value)))

    seen_dumpvars = False
    while pos < len(tokens):
        tok = tokens[pos]
        pos += 1
        if tok.startswith("#"):
            t = int(tok[1:])
            if time is not None and t <= time:
                raise VcdError(f"time {t} not after {time}")
            time = t
        elif tok == "$dumpvars":
            if seen_dumpvars or changes:
                raise VcdError("$dumpvars must come first, once")
            seen_dumpvars = True
            in_dumpvars = True
        elif tok == "$end":
            if not in_dumpvars:
                raise VcdError("stray $end")
            in_dumpvars = False
        elif tok[0] in "bBrR":
            if pos >= len(tokens):
                raise VcdError("vector without identifier")
            record(tokens[pos], tok[0].lower() + tok[1:])
            pos += 1
        elif tok[0] in "01xXzZ":
            record(tok[1:], tok[0].lower())
        else:
            raise VcdError(f"unexpected token {tok}")
    if in_dumpvars:
        raise VcdError("unterminated $dumpvars")
    declared = {name: (kind, width) for entries in vars_by_id.values() for name, kind, width in entries}
    return declared, changes


def read_expected(path):
    declared, changes = {}, []
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "var":
            declared[f[1]] = (f[2], int(f[3]))
        elif f[0] == "at":
            kind = declared[f[2]][0]
            value = f[3] if f[3] == "x" else (float(f[3]) if kind == "real" else int(f[3]))
            changes.append((int(f[1]), f[2], value))
    return declared, changes


def check_fixture(exe):
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([exe, tmp], check=True)
        want_decl, want = read_expected(os.path.join(tmp, "expected.txt"))
        failed = 0
        for name in ("trace.vcd", "stream.vcd"):
            try:
                decl, got = read_vcd(open(os.path.join(tmp, name)).read())
                if decl != want_decl:
                    raise VcdError(f"declarations differ: {decl} != {want_decl}")
                if got != want:
                    for i, (g, w) in enumerate(zip(got, want)):
                        if g != w:
                            raise VcdError(f"change {i}: read {g}, expected {w}")
                    raise VcdError(f"{len(got)} changes read, {len(want)} expected")
                print(f"{name}: {len(got)} value changes of {len(decl)} signals read back")
            except VcdError as e:
                failed += 1
                print(f"{name}: {e}")
        # The streamed file must be the batch file byte for byte (samples came in time order).
        if open(os.path.join(tmp, "trace.vcd"), "rb").read() != open(os.path.join(tmp, "stream.vcd"), "rb").read():
            failed += 1
            print("stream.vcd differs from trace.vcd")
        print(f"{3 - failed} passed, {failed} failed")
        return 1 if failed else 0


def main(argv):
    if len(argv) == 3 and argv[1] == "--check-fixture":
        return check_fixture(argv[2])
    if len(argv) == 2:
        _, changes = read_vcd(open(argv[1]).read())
        for t, name, value in changes:
            print(t, name, value)
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
