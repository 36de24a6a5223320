#!/usr/bin/env bash
# Builds everything and runs the whole test suite (Catch2 tests through CTest),
# then the Python tests against a pip install (scripts/test-python-install.sh).
# The suite includes `eccd regress cases/ --certify` over the whole corpus and
# the metamorphic tests over generated scenes; their seeds are printed at the end.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  printf '%b\n' "usage: bash scripts/run-tests.sh\n  installs what is missing, builds, and runs the whole test suite (CTest + Catch2)"
  exit 0
fi
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
# The Python package installed by pip into a fresh venv, its tests against that install.
bash scripts/test-python-install.sh
log=build/Testing/Temporary/LastTest.log
if [ -f "$log" ]; then
  echo "== metamorphic tests ran on these generated scenes (rerun: ECCD_METAMORPHIC_SEED=BASE build/eccd_tests '[metamorphic]') =="
  grep -h '^metamorphic: ' "$log" || true
  echo "== regression corpus =="
  grep -h '^regress cases/: ' "$log" || true
fi
