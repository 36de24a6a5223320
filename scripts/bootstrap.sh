#!/usr/bin/env bash
# Installs the Debian packages eccd needs (only those missing), then configures
# and builds into ./build. Used by both README commands and by .ci/run.
# ECCD_WERROR=ON (scripts/run-tests.sh, so CI) builds with warnings as errors;
# the default OFF lets a newer compiler's new warnings through.
set -euo pipefail
cd "$(dirname "$0")/.."
PACKAGES="cmake g++ make libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libflint-dev libeigen3-dev libfcl-dev catch2 nlohmann-json3-dev libcli11-dev libboost-dev python3 python3-matplotlib python3-dev pybind11-dev python3-pybind11 python3-pytest python3-numpy python3-venv python3-pip python3-setuptools python3-wheel ccache parallel chromium clang-format"
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "bootstrap: installing Debian packages:$missing" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >&2
fi
# ccache: the CTest test package_consumer builds eccd's libraries again as a
# subproject of a consumer; with the same flags and absolute paths those
# compilations are cache hits of this build.
launcher=""
command -v ccache >/dev/null && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
# The Python module for Debian's python3, whose pybind11 and numpy the packages above installed, and which
# scripts/test-python-install.sh installs the package for: then pip's build of the module (the same
# compilations, the same include paths) is cache hits of this one. CMake would otherwise take the first
# python3 on PATH (a pyenv one, say), whose headers elsewhere make every pybind11 file compile twice
# (measured in fresh-clone CI runs: pip install 79 s with the module built here for another Python, 13 s
# with this one). PYTHON chooses another interpreter, as it does for scripts/test-python-install.sh.
python=""
interpreter="${PYTHON:-/usr/bin/python3}"
[ -x "$interpreter" ] && python="-DPython_EXECUTABLE=$interpreter"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DECCD_WERROR="${ECCD_WERROR:-OFF}" $launcher $python >/dev/null
cmake --build build -j"$(nproc)" >&2
