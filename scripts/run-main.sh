#!/usr/bin/env bash
# The main job on the default input: every scene under cases/ solved in exact,
# double and MPFR arithmetic, side by side (until the robustness report lands).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
./build/eccd table cases "$@"
