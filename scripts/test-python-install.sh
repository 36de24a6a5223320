#!/usr/bin/env bash
# The Python package as a user gets it: `pip install .` (offline, no build
# isolation, Debian's setuptools, numpy and pytest) into a fresh venv, then
# the pytest suite tests/python against that install, run from outside the
# source tree so that `import eccd` can only find the installed package.
# The build reuses build-pip/ and ccache (setup.py); the install's time is
# printed. Usage: scripts/test-python-install.sh [pytest arguments]
# PYTHON: the interpreter of the venv (default /usr/bin/python3, Debian's,
# whose site-packages hold numpy and pytest).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
python="${PYTHON:-/usr/bin/python3}"
work="$(mktemp -d "${TMPDIR:-/tmp}/eccd-pyinstall.XXXXXX")"
trap 'rm -rf "$work"' EXIT
"$python" -m venv --system-site-packages "$work/venv"
start=$(date +%s)
"$work/venv/bin/pip" install --quiet --no-build-isolation --no-index --no-deps "$root" >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log" >&2; echo "test-python-install: pip install failed" >&2; exit 1; }
echo "test-python-install: pip install took $(( $(date +%s) - start )) s"
cd "$work"
"$work/venv/bin/pip" show eccd | sed -n '1,3p'
"$work/venv/bin/python" - <<'PY'
import os, sys, eccd
where = os.path.realpath(eccd.__file__)
assert where.startswith(os.path.realpath(sys.prefix)), f"eccd imported from {where}, not from the venv {sys.prefix}"
print(f"test-python-install: eccd {eccd.__version__} from {os.path.dirname(where)}")
PY
ECCD_SOURCE_DIR="$root" "$work/venv/bin/python" -m pytest -q -p no:cacheprovider "$root/tests/python" "$@"
