#!/usr/bin/env python3
"""Every citation of a manual digest in the repository resolves inside it.

A file that cites `docs/spec/<device>.md` (or its -examples.md) names a file that exists
there, a digest line `docs/spec/<device>.md L187` is within that file, a manual text
`seeds/NNN...` is one docs/spec/README.md names, no citation is left without its docs/
folder (a bare spec/<device>.md points at nothing), and no file names a path of the machine
it was written on. Usage: doc_citations.py SOURCE_DIR
"""
import os
import re
import sys

TEXT = (".cpp", ".hpp", ".h", ".md", ".toml", ".txt", ".py", ".sh", ".cmake", ".json", ".yml", ".yaml")
SKIP_DIRS = {".git", "__pycache__"}

DEVICES = r"(?:ans1|smd23e|pls2700|ssi7361|amci4501)(?:-examples)?\.md"
CITED = re.compile(r"docs/spec/(" + DEVICES + r")(?:\s+(L\d+))?")
BARE = re.compile(r"(?<![\w/])(?:shared/)?spec/" + DEVICES)
SEED = re.compile(r"seeds/(\d{3})(_[0-9a-f]+\.txt)?")
# Built from parts so this file does not name them itself.
MACHINE_PATHS = re.compile("/" + "work/|/" + "root/|/" + "home/")


def source_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        rel = os.path.relpath(dirpath, root)
        dirnames[:] = [d for d in dirnames
                       if d not in SKIP_DIRS and not (rel == "." and d.startswith("build"))]
        for name in filenames:
            if name.endswith(TEXT) or name in ("Makefile", "CMakeLists.txt", "run"):
                yield os.path.join(dirpath, name)


def main():
    root = sys.argv[1]
    spec = os.path.join(root, "docs", "spec")
    lines_of = {}
    for name in os.listdir(spec):
        with open(os.path.join(spec, name), encoding="utf-8") as f:
            lines_of[name] = sum(1 for _ in f)
    with open(os.path.join(spec, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    seeds = {m.group(1): m.group(0) for m in SEED.finditer(readme) if m.group(2)}

    problems = []
    checked = 0
    fuzz_seeds = os.path.join("fuzz", "")
    for path in source_files(root):
        rel = os.path.relpath(path, root)
        with open(path, encoding="utf-8", errors="replace") as f:
            for n, line in enumerate(f, 1):
                where = f"{rel}:{n}"
                for m in CITED.finditer(line):
                    checked += 1
                    name, at = m.group(1), m.group(2)
                    if name not in lines_of:
                        problems.append(f"{where}: docs/spec/{name} does not exist")
                    elif at and int(at[1:]) > lines_of[name]:
                        problems.append(f"{where}: docs/spec/{name} {at} is past its {lines_of[name]} lines")
                for m in BARE.finditer(line):
                    problems.append(f"{where}: '{m.group(0)}' is not in the repository: cite docs/spec/...")
                for m in SEED.finditer(line):
                    if "fuzz/seeds" in line or rel.startswith(fuzz_seeds):
                        continue
                    checked += 1
                    full = seeds.get(m.group(1))
                    if full is None or (m.group(2) and m.group(0) != full):
                        problems.append(f"{where}: {m.group(0)} is no manual docs/spec/README.md names")
                if MACHINE_PATHS.search(line):
                    problems.append(f"{where}: names a path of this machine")
    for p in problems:
        print(p)
    print(f"{checked} citations checked")
    if checked == 0:
        print("no citation found: the scan read nothing")
        return 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
