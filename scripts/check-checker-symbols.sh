#!/usr/bin/env bash
# eccd-check shares no code with the provers (docs/checking.md): the symbols
# of the program (nm -C) may name the checker's own namespace eccd::check and
# the libraries it links (GMP, MPFR, MPFI, the C++ runtime), but no CGAL and
# no other eccd:: function (a pipeline, an isolator, a prover's algebra).
# Usage: check-checker-symbols.sh PATH/TO/eccd-check. Prints every offending
# symbol and exits 1 if there is one.
set -euo pipefail
exe=${1:?usage: check-checker-symbols.sh PATH/TO/eccd-check}
[ -x "$exe" ] || { echo "check-checker-symbols: $exe is not an executable"; exit 2; }
syms=$(nm -C "$exe")
[ -n "$syms" ] || { echo "check-checker-symbols: nm printed no symbols for $exe (stripped?)"; exit 2; }
bad=$(sed 's/eccd::check:://g' <<<"$syms" | grep -E 'CGAL|eccd::|flint|fmpz' || true)
if [ -n "$bad" ]; then
  head -20 <<<"$bad"
  echo "check-checker-symbols: $exe names $(wc -l <<<"$bad") symbol(s) of CGAL, FLINT or eccd outside eccd::check (see above)"
  exit 1
fi
echo "check-checker-symbols: $exe names no CGAL, no FLINT and no eccd function outside eccd::check ($(wc -l <<<"$syms") symbols)"
