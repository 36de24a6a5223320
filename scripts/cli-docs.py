#!/usr/bin/env python3
"""Keep the "## Options" section of each docs/cli/<command>.md equal to `eccd <command> --help`.

Usage:  python3 scripts/cli-docs.py ECCD_EXE            rewrite the sections from the program
        python3 scripts/cli-docs.py --check ECCD_EXE    exit 1 and name each page that differs (CTest cli_docs)

Run it after adding or renaming an option. The program's path in the "Usage:" line is written as `eccd`.
"""
import os
import re
import subprocess
import sys

COMMANDS = ["solve", "table", "certify", "check-certificate", "regress", "generate", "report", "plot", "judge", "fcl",
            "separate", "animate"]
HEAD = ("## Options\n\nThe output of `eccd {c} --help`; every command also takes the options of "
        "[the command line's conventions](README.md#conventions-and-limits) (`--time-limit`, `--memory-limit`, "
        "`--max-file-bytes`, `--max-digits`, `--max-degree`, `--quiet`).\n\n```text\n{h}\n```\n")


def help_text(exe, command):
    r = subprocess.run([exe, command, "--help"], capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        raise SystemExit(f"cli-docs.py: {exe} {command} --help: exit {r.returncode}: {r.stderr.strip()}")
    lines = [l.rstrip() for l in r.stdout.splitlines()]
    lines = [re.sub(r"^Usage: \S+ ", "Usage: eccd ", l) for l in lines]
    while lines and not lines[-1]:
        lines.pop()
    return "\n".join(lines)


def main(argv):
    check = "--check" in argv[1:]
    args = [a for a in argv[1:] if a != "--check"]
    if len(args) != 1:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    exe = args[0]
    docs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "cli")
    stale = []
    for c in COMMANDS:
        path = os.path.join(docs, c + ".md")
        if not os.path.exists(path):
            stale.append(f"{path}: missing")
            continue
        text = open(path, encoding="utf-8").read()
        want = HEAD.format(c=c, h=help_text(exe, c))
        i = text.find("\n## Options\n")
        new = (text[:i + 1] if i >= 0 else text.rstrip("\n") + "\n\n") + want
        if new != text:
            if check:
                stale.append(f"{path}: its Options section differs from `eccd {c} --help`")
            else:
                with open(path, "w", encoding="utf-8") as fh:
                    fh.write(new)
                print(f"cli-docs.py: rewrote the Options of {path}")
    for s in stale:
        print(s)
    if stale and check:
        print("run: python3 scripts/cli-docs.py build/eccd")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
