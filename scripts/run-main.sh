#!/usr/bin/env bash
# The main job on the default input: the robustness report (2D and 3D, motion
# degrees 2-6, every family, every pipeline, plus the shipped cases under
# cases/) written to a NEW folder reports/run-YYYYMMDD-HHMMSS/ (UTC start
# time; report.md, results.csv, PNG figures), printed at the end. Extra
# arguments go to `eccd report` (e.g. --seed 7 --name mine); `--name default`
# refreshes the checked-in example reports/default/. After Ctrl-C or a crash,
# the same arguments plus `--resume` continue the run (eccd prints the command).
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  printf '%b\n' "usage: bash scripts/run-main.sh [eccd report OPTIONS]\n  installs what is missing, builds, and writes the robustness report into a new reports/run-YYYYMMDD-HHMMSS/\n  (report.html, report.md, results.csv, figures); OPTIONS go to eccd report (build/eccd report --help)"
  exit 0
fi
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
rc=0
file=$(./build/eccd report "$@") || rc=$?
if [ -n "$file" ]; then
  printf '%s\n' "$file"
  printf 'run-main: the report is in %s/\n' "$(dirname "$file")"
fi
exit "$rc"
