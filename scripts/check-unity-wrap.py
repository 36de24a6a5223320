#!/usr/bin/env python3
"""Every test file of eccd_tests keeps its body in `namespace ECCD_UNITY_ID { ... }` (docs/testing.md):
the test files are compiled eight to a translation unit (a unity build), and the per-file namespace keeps
two files' helpers of the same name apart. Checks each tests/**/*.cpp (tests/main.cpp, which only defines
Catch2's main, and tests/package/, a separate project, aside): the namespace opens after the last
#include and closes on the file's last line. Prints each file that does not, exit 1; else one line, exit 0.
"""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
OPEN = "namespace ECCD_UNITY_ID {"
CLOSE = "}  // namespace ECCD_UNITY_ID"


def problem(path):
    lines = path.read_text(encoding="utf-8").rstrip("\n").split("\n")
    if OPEN not in lines:
        return f"no line `{OPEN}`"
    opening = lines.index(OPEN)
    includes = [i for i, line in enumerate(lines) if line.startswith("#include")]
    if includes and includes[-1] > opening:
        return f"an #include (line {includes[-1] + 1}) after `{OPEN}` (line {opening + 1})"
    if lines[-1] != CLOSE:
        return f"the last line is not `{CLOSE}`"
    return None


def main():
    files = [p for p in sorted((ROOT / "tests").rglob("*.cpp"))
             if p.relative_to(ROOT).as_posix() != "tests/main.cpp" and "package" not in p.relative_to(ROOT).parts]
    bad = [(p, problem(p)) for p in files]
    bad = [(p, why) for p, why in bad if why]
    for p, why in bad:
        print(f"{p.relative_to(ROOT)}: {why} (docs/testing.md: the unity build of the tests)")
    if bad:
        return 1
    print(f"check-unity-wrap: {len(files)} test files keep their body in namespace ECCD_UNITY_ID")
    return 0


if __name__ == "__main__":
    sys.exit(main())
