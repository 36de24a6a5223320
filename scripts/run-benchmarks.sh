#!/usr/bin/env bash
# The performance benchmark: installs the Debian packages it needs
# (only those missing, as scripts/bootstrap.sh does for the main build),
# configures and builds the eccd_bench target (and the eccd program, for the
# certificates' checking/proving figures) in ./build-bench (Release; the
# benchmark is not part of the normal build or the tests), runs it, profiles
# every missed target with perf when perf works, and writes
# reports/performance.md (bench/performance_report.py). About 5 to 10 minutes
# on 2 cores from a clean checkout, most of it the build.
# Extra arguments go to bench/performance_report.py (e.g. --quick, --no-perf).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(python3 -c 'import time; print(time.time())' 2>/dev/null || date +%s)

# The main build's packages plus the benchmark's own: Google Benchmark, MPSolve,
# and perf (linux-perf) for the profiles of missed targets (optional: the
# report says so when it is missing or not allowed to run).
PACKAGES="cmake g++ make libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libflint-dev libeigen3-dev catch2 nlohmann-json3-dev libcli11-dev libboost-dev python3 libbenchmark-dev libmps-dev libfcl-dev"
OPTIONAL="linux-perf"
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
if [ -n "$missing" ]; then
  echo "run-benchmarks: installing Debian packages:$missing" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >&2
fi
if ! command -v perf >/dev/null 2>&1; then
  echo "run-benchmarks: trying to install $OPTIONAL (profiles of missed targets)" >&2
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $OPTIONAL >&2 ||
    echo "run-benchmarks: no perf; the report gives the phase breakdown only" >&2
fi

# ccache as in scripts/bootstrap.sh: with the same flags (warnings as errors, as scripts/run-tests.sh builds)
# the benchmark's build reuses the main build's objects.
launcher=""
command -v ccache >/dev/null && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DECCD_WERROR=ON $launcher >/dev/null
cmake --build build-bench -j"$(nproc)" --target eccd_bench eccd >&2

python3 bench/performance_report.py --bench build-bench/bench/eccd_bench --out reports/performance.md \
  --work build-bench/bench-results --started "$started" "$@"
