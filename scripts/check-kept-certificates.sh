#!/usr/bin/env bash
# The certificates of `eccd regress cases/ --certify` through both independent
# checkers (docs/checking.md): writes them with --keep-certificates into a
# temporary folder, then runs eccd-check on every certificate of the index in
# a format it covers (eccd-certificate/2, eccd-bezier-certificate/2,
# eccd-cycloidal-certificate/2, eccd-independent-certificate/3; the Bezier ones from a second run with
# --arith certified) and tools/check_certificate.py --index on the first run's.
# Exit 0 only if every one is VALID.
# Usage: check-kept-certificates.sh PATH/TO/eccd PATH/TO/eccd-check [CASES_DIR]
set -euo pipefail
eccd=${1:?usage: check-kept-certificates.sh ECCD ECCD_CHECK [CASES_DIR]}
checker=${2:?usage: check-kept-certificates.sh ECCD ECCD_CHECK [CASES_DIR]}
src=$(cd "$(dirname "$0")/.." && pwd)
cases=${3:-$src/cases}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$eccd" regress "$cases" --certify --keep-certificates "$dir" >"$dir/regress.txt" || { tail -20 "$dir/regress.txt"; exit 1; }
"$eccd" regress "$cases" --arith certified --certify --keep-certificates "$dir/certified" >"$dir/regress-certified.txt" || { tail -20 "$dir/regress-certified.txt"; exit 1; }
n=0; bad=0
for sub in "" certified; do
  d="$dir${sub:+/$sub}"
  while IFS=$'\t' read -r scene cert; do
    n=$((n + 1))
    if ! "$checker" "$scene" "$d/$cert" >"$dir/out.txt" 2>&1; then
      bad=$((bad + 1)); echo "eccd-check: NOT VALID: $cert"; tail -1 "$dir/out.txt"
    fi
  done < <(python3 -c 'import json,sys; [print(e["scene"] + "\t" + e["certificate"]) for e in json.load(open(sys.argv[1]))["certificates"] if e["format"] in ("eccd-certificate/2", "eccd-bezier-certificate/2", "eccd-cycloidal-certificate/2", "eccd-independent-certificate/3")]' "$d/index.json")
done
echo "eccd-check: $((n - bad)) of $n certificate(s) VALID (eccd-certificate/2, eccd-bezier-certificate/2, eccd-cycloidal-certificate/2, eccd-independent-certificate/3; both runs)"
python3 "$src/tools/check_certificate.py" --index "$dir/index.json"
[ "$bad" -eq 0 ] && [ "$n" -gt 0 ]
