#!/usr/bin/env bash
# Builds everything with warnings as errors (-DECCD_WERROR=ON, the pip build's
# too) and runs the whole test suite (Catch2 tests through CTest),
# then the Python tests against a pip install (scripts/test-python-install.sh).
# The suite includes `eccd regress cases/ --certify` over the whole corpus and
# the metamorphic tests over generated scenes; their seeds are printed at the end.
# The tests labelled `budget` (Catch2 tag [budget]: runs under a time budget)
# run last, after the Python tests, with one busy process per core beside them (every core shared by a
# test and a busy loop at -j$(nproc)): their bounds are processor time or work counts, so a busy machine
# must not fail them.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  printf '%b\n' "usage: bash scripts/run-tests.sh\n  installs what is missing, builds, and runs the whole test suite (CTest + Catch2)"
  exit 0
fi
cd "$(dirname "$0")/.."
ECCD_WERROR=ON bash scripts/bootstrap.sh
status=0
ctest --test-dir build --output-on-failure -j"$(nproc)" -LE budget || status=$?
log=build/Testing/Temporary/LastTest.log
saved=build/Testing/Temporary/LastTest-unbudgeted.log
if [ -f "$log" ]; then cp "$log" "$saved"; fi
# The Python package installed by pip into a fresh venv, its tests against that install.
ECCD_CMAKE_ARGS="-DECCD_WERROR=ON ${ECCD_CMAKE_ARGS:-}" bash scripts/test-python-install.sh || status=$?
busy=()
stop_busy() {
  for p in "${busy[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${busy[@]}"; do wait "$p" 2>/dev/null || true; done
  busy=()
}
trap stop_busy EXIT INT TERM HUP
for _ in $(seq "$(nproc)"); do
  yes > /dev/null &
  busy+=($!)
done
echo "== the tests labelled budget, with ${#busy[@]} busy processes beside them =="
ctest --test-dir build --output-on-failure -j"$(nproc)" -L budget || status=$?
stop_busy
if [ -f "$saved" ]; then
  log=$saved
  echo "== metamorphic tests ran on these generated scenes (rerun: ECCD_METAMORPHIC_SEED=BASE build/eccd_tests '[metamorphic]') =="
  grep -h '^metamorphic: ' "$log" || true
  echo "== regression corpus =="
  grep -h '^regress cases/: ' "$log" || true
fi
exit "$status"
