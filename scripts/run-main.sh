#!/usr/bin/env bash
# The main job on the default input: the robustness report (2D and 3D, motion
# degrees 2-6, every family, every pipeline, plus the shipped cases under
# cases/) written to reports/default/ (report.md, results.csv, PNG figures).
# Extra arguments go to `eccd report` (e.g. --seed 7 --name mine).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
./build/eccd report "$@"
