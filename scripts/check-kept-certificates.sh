#!/usr/bin/env bash
# The certificates of `eccd regress cases/ --certify` through both independent
# checkers (docs/checking.md): writes them with --keep-certificates into a
# temporary folder, then runs eccd-check on every eccd-certificate/2 of the
# index and tools/check_certificate.py --index on all of them. Exit 0 only if
# every one is VALID in both.
# Usage: check-kept-certificates.sh PATH/TO/eccd PATH/TO/eccd-check [CASES_DIR]
set -euo pipefail
eccd=${1:?usage: check-kept-certificates.sh ECCD ECCD_CHECK [CASES_DIR]}
checker=${2:?usage: check-kept-certificates.sh ECCD ECCD_CHECK [CASES_DIR]}
src=$(cd "$(dirname "$0")/.." && pwd)
cases=${3:-$src/cases}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$eccd" regress "$cases" --certify --keep-certificates "$dir" >"$dir/regress.txt" || { tail -20 "$dir/regress.txt"; exit 1; }
n=0; bad=0
while IFS=$'\t' read -r scene cert; do
  n=$((n + 1))
  if ! "$checker" "$scene" "$dir/$cert" >"$dir/out.txt" 2>&1; then
    bad=$((bad + 1)); echo "eccd-check: NOT VALID: $cert"; tail -1 "$dir/out.txt"
  fi
done < <(python3 -c 'import json,sys; [print(e["scene"] + "\t" + e["certificate"]) for e in json.load(open(sys.argv[1]))["certificates"] if e["format"] == "eccd-certificate/2"]' "$dir/index.json")
echo "eccd-check: $((n - bad)) of $n eccd-certificate/2 certificate(s) VALID"
python3 "$src/tools/check_certificate.py" --index "$dir/index.json"
[ "$bad" -eq 0 ] && [ "$n" -gt 0 ]
