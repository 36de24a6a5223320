#!/usr/bin/env python3
"""History stays out of the code (CTest `house_history`).

Comments and strings of the non-test sources say what the code does and why,
now; which issue asked for it and what it replaced belong in the commit
messages and CHANGELOG.md. This check fails, naming file and line, on any
"issue N" (also "issues 14 and 15", "issue-21", "Issue #6"), "used to" or
"as before" in the sources: the library folders, app/, python/, include/,
bench/, scripts/, tools/, cmake/, docs/ and the CMakeLists.txt files.
tests/, cases/, reports/ and CHANGELOG.md are out of scope (tests may name
the issue they pin down).

"used to" is also plain English ("never used to decide" = employed to
decide): such lines are allowed by scripts/check-history-allow.txt, one
`PATH: TEXT` per line (TEXT a piece of the line, matched as written), each
reviewed by hand. Usage: python3 scripts/check-history.py  (exit 1 on a hit).
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ["number", "kernel", "solution", "floating", "exact", "certified", "io", "certificate", "api", "compare",
           "app", "python", "include", "bench", "scripts", "tools", "cmake", "docs"]
SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".pyi", ".sh", ".cmake", ".in", ".md", ".txt")
PATTERN = re.compile(r"\b[Ii]ssues?[- ]#?[0-9]+|\b[Ii]ssues [0-9]+ and [0-9]+|\bused to\b|\b[Aa]s before\b")
ALLOW_FILE = os.path.join("scripts", "check-history-allow.txt")
SELF = {os.path.join("scripts", "check-history.py"), ALLOW_FILE}


def sources():
    yield "CMakeLists.txt"
    for folder in FOLDERS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, folder)):
            dirnames[:] = sorted(d for d in dirnames if d != "__pycache__")
            for name in sorted(filenames):
                if name.endswith(SUFFIXES):
                    yield os.path.relpath(os.path.join(dirpath, name), ROOT)


def allowed():
    out = []
    with open(os.path.join(ROOT, ALLOW_FILE), encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line.strip() or line.startswith("#"):
                continue
            path, _, text = line.partition(": ")
            out.append((path, text))
    return out


def main():
    allow = allowed()
    used = set()
    hits = []
    for rel in sources():
        if rel in SELF:
            continue
        try:
            with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
                lines = f.readlines()
        except (UnicodeDecodeError, OSError):
            continue
        for no, line in enumerate(lines, 1):
            if not PATTERN.search(line):
                continue
            ok = [i for i, (p, t) in enumerate(allow) if p == rel and t in line]
            if ok:
                used.update(ok)
                continue
            hits.append(f"{rel}:{no}: {line.strip()[:160]}")
    stale = [f"{p}: {t}" for i, (p, t) in enumerate(allow) if i not in used]
    if hits:
        print("history in the code (\"issue N\", \"used to\", \"as before\"): say what the code does now;")
        print("the history goes into the commit message and CHANGELOG.md (scripts/check-history.py):")
        print("\n".join(hits))
    if stale:
        print(f"entries of {ALLOW_FILE} that match no line any more (remove them):")
        print("\n".join(stale))
    if hits or stale:
        return 1
    print("history: no \"issue N\", \"used to\" or \"as before\" in the sources")
    return 0


if __name__ == "__main__":
    sys.exit(main())
