#!/usr/bin/env bash
# The layers' include arrows point one way (docs/architecture.md, "Layers, folder by folder"):
#   number -> kernel -> solution -> floating | exact -> certified -> io -> certificate -> api -> compare -> app
# (solution/: the answer types every layer above shares; io/: the file
# formats, which the certificate writers of certificate/write/ read scenes with).
# A file may include headers of its own folder and of layers strictly below
# it (floating and exact are siblings: neither includes the other). Prints
# every include that points up or sideways and exits 1 if there is one.
# The independent checker certificate/check/ is stricter (docs/checking.md):
# it shares no code with the provers, so it includes only number/ and its own
# folder, and no CGAL or FLINT header; that is checked too.
# The grep it runs:  grep -n '#include' number kernel solution floating exact certified io certificate api compare app include
set -euo pipefail
cd "$(dirname "$0")/.."
rank() {
  case "$1" in
    number) echo 0 ;; kernel) echo 1 ;; solution) echo 2 ;; floating|exact) echo 3 ;; certified) echo 4 ;;
    io) echo 5 ;; certificate) echo 6 ;; api) echo 7 ;; include|compare) echo 8 ;; app) echo 9 ;; *) echo 99 ;;
  esac
}
bad=0
while IFS= read -r line; do
  file=${line%%:*}; rest=${line#*:}; lineno=${rest%%:*}
  inc=$(sed -n 's/.*#include "\([^"]*\)".*/\1/p' <<<"$rest")
  from=${file%%/*}; to=${inc%%/*}
  [ "$to" = "$inc" ] && continue          # a file of the same folder, included by bare name
  [ "$from" = "$to" ] && continue
  [ "$from" = include ] && [ "$to" = eccd ] && continue
  if [ "$(rank "$to")" -ge "$(rank "$from")" ]; then
    echo "$file:$lineno: $from/ includes $inc (layer $to/ is not below $from/)"
    bad=1
  fi
done < <(grep -rn '#include "' number kernel solution floating exact certified io certificate api compare app include --include='*.hpp' --include='*.cpp')
# The checker's isolation: certificate/check/ includes number/, its own folder
# and system or third-party headers other than CGAL and FLINT, nothing else.
if [ -d certificate/check ]; then
  while IFS= read -r line; do
    file=${line%%:*}; rest=${line#*:}; lineno=${rest%%:*}
    inc=$(sed -n 's/.*#include *[<"]\([^">]*\)[">].*/\1/p' <<<"$rest")
    case "$inc" in
      number/*|certificate/check/*) ;;                      # the number layer and the checker's own files
      gmp.h|gmpxx.h|mpfr.h|mpfi.h|nlohmann/json.hpp) ;;     # the number libraries and the JSON parser
      *.h|*.hpp|*/*) echo "$file:$lineno: the independent checker includes $inc (allowed: number/, certificate/check/, GMP, MPFR, MPFI, nlohmann json, the standard library)"; bad=1 ;;
    esac
  done < <(grep -rn '#include' certificate/check --include='*.hpp' --include='*.cpp')
fi
if [ "$bad" -ne 0 ]; then echo "check-layers: an include arrow points up or sideways (see above)"; exit 1; fi
echo "check-layers: every include arrow points down (number -> kernel -> solution -> floating|exact -> certified -> io -> certificate -> api -> compare -> app); certificate/check includes only number/ and itself"
