#!/usr/bin/env bash
# Builds everything and runs the whole test suite (Catch2 tests through CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
