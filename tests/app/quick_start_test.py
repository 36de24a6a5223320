#!/usr/bin/env python3
"""CTest quick_start: every command of README.md's "## Quick start", run as a newcomer would.

Usage: python3 tests/app/quick_start_test.py ECCD_EXE SOURCE_DIR

Reads the section "## Quick start" of SOURCE_DIR/README.md and runs, in a fresh folder that holds links
`cases` -> SOURCE_DIR/cases and `build/eccd` -> ECCD_EXE (so the lines run exactly as written):
  - `bash scripts/...` lines: the script exists and its --help exits 0 and prints a usage line (the scripts
    themselves build and run everything: CI runs them);
  - `build/eccd ...` lines: as written, each must exit 0; a `--out FILE` or `--out-dir DIR` must then exist
    (a report folder with report.md and report.html);
  - ```python blocks: run with the built module (PYTHONPATH = the folder of ECCD_EXE + /python) and must
    exit 0; a line's trailing comment `# X Y` is not checked, the printed answer is (True for collides);
  - `pip install` lines are not run here (they build the module again; tests/python covers the module), and
    the C++ lines are the CTest test package_consumer.
Exit 0 pass, 1 fail (each failure printed).
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

FAILS = []


def check(ok, what, detail=""):
    print(("ok    " if ok else "FAIL  ") + what + (f" ({detail})" if detail and not ok else ""), flush=True)
    if not ok:
        FAILS.append(what)


def quick_start(readme):
    m = re.search(r"^## Quick start\s*$(.*?)(?=^## )", readme, flags=re.M | re.S)
    if not m:
        return None
    blocks = re.findall(r"^```(\w+)\s*$(.*?)^```\s*$", m.group(1), flags=re.M | re.S)
    return [(lang, body) for lang, body in blocks]


def strip_comment(line):
    """The command without its trailing '# ...' comment (a '#' inside quotes stays)."""
    out, quote = [], None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1].isspace()):
            break
        out.append(ch)
    return "".join(out).strip()


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    exe, src = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    blocks = quick_start(open(os.path.join(src, "README.md"), encoding="utf-8").read())
    check(blocks is not None and len(blocks) > 0, "README.md has a '## Quick start' with code blocks")
    if not blocks:
        return 1
    work = tempfile.mkdtemp(prefix="eccd-quickstart-")
    try:
        os.symlink(os.path.join(src, "cases"), os.path.join(work, "cases"))
        os.makedirs(os.path.join(work, "build"))
        os.symlink(exe, os.path.join(work, "build", "eccd"))
        env = dict(os.environ, PYTHONPATH=os.path.join(os.path.dirname(exe), "python"))
        ran = {"scripts": 0, "eccd": 0, "python": 0}
        for lang, body in blocks:
            if lang == "python":
                r = subprocess.run([sys.executable, "-c", body], cwd=work, env=env, capture_output=True, text=True,
                                   timeout=300)
                check(r.returncode == 0, "the Python lines run", f"exit {r.returncode}; {r.stderr.strip()[-300:]}")
                check(r.stdout.startswith("True"), f"the Python lines print the answer ({r.stdout.strip()[:80]!r})")
                ran["python"] += 1
                continue
            if lang != "sh":
                continue  # cmake, cpp: the CTest test package_consumer builds and runs a consumer
            for raw in body.splitlines():
                line = strip_comment(raw)
                if not line:
                    continue
                words = shlex.split(line)
                if words[0] == "bash" and len(words) > 1 and words[1].startswith("scripts/"):
                    script = os.path.join(src, words[1])
                    check(os.path.isfile(script), f"{words[1]} exists")
                    r = subprocess.run(["bash", script, "--help"], capture_output=True, text=True, timeout=60)
                    check(r.returncode == 0 and r.stdout.startswith("usage:"),
                          f"bash {words[1]} --help prints its usage", f"exit {r.returncode}")
                    ran["scripts"] += 1
                elif words[0] == "build/eccd":
                    r = subprocess.run(line, shell=True, cwd=work, capture_output=True, text=True, timeout=900)
                    check(r.returncode == 0, line, f"exit {r.returncode}; {r.stderr.strip()[-300:]}")
                    check("warning" not in r.stderr, f"{words[1]}: no warning on stderr (the quick start uses today's option names)")
                    if "--out-dir" in words:
                        d = os.path.join(work, words[words.index("--out-dir") + 1])
                        for f in ("report.md", "report.html", "results.csv"):
                            check(os.path.isfile(os.path.join(d, f)), f"{words[1]} wrote {f}")
                    elif "--out" in words:
                        check(os.path.isfile(os.path.join(work, words[words.index("--out") + 1])), f"{words[1]} wrote its --out file")
                    ran["eccd"] += 1
                elif words[:2] == ["pip", "install"]:
                    print(f"skip  {line} (builds the module again; tests/python checks the module)")
                else:
                    check(False, f"a quick-start line this test does not know how to run: {line}")
        check(ran["scripts"] == 2, f"both set-up scripts were checked ({ran['scripts']})")
        check(ran["eccd"] >= 3, f"the eccd lines ran ({ran['eccd']})")
        check(ran["python"] >= 1, f"the Python block ran ({ran['python']})")
        return 1 if FAILS else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
