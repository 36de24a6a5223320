#!/usr/bin/env python3
"""The map from library headers to their tests (docs/testing.md, "Where a test lives").

A library header LAYER/.../NAME.hpp with logic is tested in tests/LAYER/test_NAME.cpp.
A header has logic when it defines a function body or has a source file NAME.cpp beside it;
a header of declarations only (options, enums, plain structs) needs no test file of its own.
A command of app/ (app/NAME.cpp with no header) is tested in tests/app/test_cli_NAME.cpp; the program's headers
whose code runs only inside it are tested through the program, in the test file THROUGH_PROGRAM names.

Usage:
  scripts/list-untested-headers.py              every header with logic, its test file or "-",
                                                and how many other test files include it; then the
                                                test files named by topic (no header of that name)
  scripts/list-untested-headers.py --untested   only the headers without a test file
  scripts/list-untested-headers.py --spec LAYER the Catch2 test spec that selects the tests of
                                                tests/LAYER/ (for `eccd_tests -# SPEC`: Catch2 tags
                                                every test with [#FILE] when given -#)
Exit status 0, or 2 for a bad argument. Standard library only.
"""
import os
import re
import sys

LAYERS = ["number", "kernel", "solution", "floating", "exact", "certified", "io", "certificate", "api", "compare",
          "app"]
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# A function body: ") [const] [noexcept] [-> type] {" (inline functions, templates, members, lambdas in them).
BODY = re.compile(r"\)\s*(const\s*)?(noexcept\s*)?(->\s*[\w:<>,\s&*]+)?\{")


def rel(path):
    return os.path.relpath(path, ROOT)


def library_headers():
    out = []
    for layer in LAYERS:
        for dirpath, _, files in os.walk(os.path.join(ROOT, layer)):
            for f in sorted(files):
                if f.endswith(".hpp"):
                    out.append(os.path.join(dirpath, f))
    return sorted(out)


def has_logic(header):
    if os.path.exists(header[: -len(".hpp")] + ".cpp"):
        return True
    with open(header, encoding="utf-8") as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    return BODY.search(text) is not None


def test_files():
    out = []
    for dirpath, _, files in os.walk(os.path.join(ROOT, "tests")):
        if "/tests/package" in dirpath + "/":
            continue
        out.extend(os.path.join(dirpath, f) for f in files if f.startswith("test_") and f.endswith(".cpp"))
    return sorted(out)


def includes(path):
    with open(path, encoding="utf-8") as f:
        return set(re.findall(r'#include\s+"([^"]+)"', f.read()))


# Headers of the program eccd (app/) whose code runs only inside the program: the test binary does not link app/,
# so their test is the program's, in the test file named here (what it checks of the header, in brackets).
THROUGH_PROGRAM = {
    "app/commands.hpp": "tests/app/test_cli_conventions.cpp",  # --quiet, exit codes, "format"/"version" stamps
    "app/option_names.hpp": "tests/app/test_cli_names.cpp",  # the old option spellings, their warning
    "app/report_parts.hpp": "tests/app/test_cli_report.cpp",  # the report's task pool, resume and output
}


def expected_test(header):
    through = THROUGH_PROGRAM.get(rel(header))
    if through:
        return os.path.join(ROOT, through)
    layer = rel(header).split(os.sep)[0]
    name = os.path.basename(header)[: -len(".hpp")]
    return os.path.join(ROOT, "tests", layer, "test_" + name + ".cpp")


def app_commands():
    app = os.path.join(ROOT, "app")
    return sorted(os.path.join(app, f) for f in os.listdir(app)
                  if f.endswith(".cpp") and f != "main.cpp" and not os.path.exists(os.path.join(app, f[:-4] + ".hpp")))


def layer_spec(layer):
    folder = os.path.join(ROOT, "tests", layer)
    if not os.path.isdir(folder):
        sys.stderr.write("no folder tests/%s\n" % layer)
        sys.exit(2)
    stems = sorted(f[:-4] for f in os.listdir(folder) if f.startswith("test_") and f.endswith(".cpp"))
    return ",".join("[#%s]~[.]" % s for s in stems)


def main(argv):
    if len(argv) == 2 and argv[0] == "--spec":
        print(layer_spec(argv[1]))
        return 0
    if argv not in ([], ["--untested"]):
        sys.stderr.write(__doc__)
        return 2
    only_untested = argv == ["--untested"]
    tests = test_files()
    incl = {t: includes(t) for t in tests}
    claimed = set()
    rows = []
    for h in library_headers():
        if not has_logic(h):
            continue
        want = expected_test(h)
        have = want in incl
        if have:
            claimed.add(want)
        others = sum(1 for t, inc in incl.items() if t != want and rel(h) in inc)
        rows.append((rel(h), rel(want) if have else "-", others))
    for c in app_commands():
        want = os.path.join(ROOT, "tests", "app", "test_cli_" + os.path.basename(c)[:-4] + ".cpp")
        have = want in incl
        if have:
            claimed.add(want)
        rows.append((rel(c), rel(want) if have else "-", 0))
    untested = [r for r in rows if r[1] == "-"]
    width = max(len(r[0]) for r in rows)
    for h, t, others in rows:
        if only_untested and t != "-":
            continue
        note = "  (+%d other test file(s) include it)" % others if others else ""
        print("%-*s  %s%s" % (width, h, t, note))
    print("\n%d of %d headers and commands with logic have a test file of their own; %d have none."
          % (len(rows) - len(untested), len(rows), len(untested)))
    if not only_untested:
        topic = [rel(t) for t in tests if t not in claimed]
        print("\nTest files named by topic (no header or command of their name):")
        for t in topic:
            print("  " + t)
        stems = {}
        for t in tests:
            stems.setdefault(os.path.basename(t), []).append(rel(t))
        same = [v for v in stems.values() if len(v) > 1]
        if same:
            print("\nTest files with the same name ([#FILE] selects them together):")
            for v in same:
                print("  " + ", ".join(v))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
