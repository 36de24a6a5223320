#!/usr/bin/env bash
# The three paper reproductions on animations (issue 17 point 5), into
# reports/animation/: report.md (each figure next to the paper's) and
# summary.json (what it was made from). The animation files and the full
# `eccd animate --json` answers go to reports/animation/generated/ (not
# committed; written again on every run).
#  (a) paper 000 Table 1: two ellipsoids 3,3,5, centres 8 apart, 0.1, 0.5, 1 rad per frame, with and without planes;
#  (b) paper 000 Table 2: a sphere orbiting an ellipsoid 4.5,4,2; certified against FCL (eccd fcl) per frame;
#  (c) paper 001 section 5 in spirit: two figures of 24 ellipsoids, 576 pairs per frame, double and certified.
# Sizes (environment): T1_FRAMES (double, default 10000), T1_CERT_FRAMES (certified, default 1000),
# T2_FRAMES (default 629: one orbit), BOX_FRAMES (double, 1000), BOX_CERT_FRAMES (certified, 200):
# certified is far slower than double here (about 12-45 ms per frame for (a), 0.5 s for (c) on this machine, unloaded).
# Single-pair runs go two at a time (2 cores); per-frame times are each run's own thread time..
# Builds eccd first if build/eccd is missing (scripts/bootstrap.sh, like run-main.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/eccd ] || bash scripts/bootstrap.sh
E=build/eccd
OUT=reports/animation
G=$OUT/generated
T1_FRAMES=${T1_FRAMES:-10000}
T1_CERT_FRAMES=${T1_CERT_FRAMES:-1000}
T2_FRAMES=${T2_FRAMES:-629}
BOX_FRAMES=${BOX_FRAMES:-1000}
BOX_CERT_FRAMES=${BOX_CERT_FRAMES:-200}
GEN=cases/animations/make_repro.py
rm -rf "$G"
mkdir -p "$G"
start=$(date +%s)
run() {  # name file arith [extra...]
  local name=$1 file=$2 arith=$3
  shift 3
  echo "run-animation-report: $name ($arith $*)" >&2
  "$E" animate "$file" --arith "$arith" --json --quiet "$@" --out "$G/$name.json"
}
for rate in 0.1 0.5 1; do
  python3 "$GEN" table1 --rate "$rate" --frames "$T1_FRAMES" --seed 1 "$G/table1-$rate.anim.json"
  python3 "$GEN" table1 --rate "$rate" --frames "$T1_CERT_FRAMES" --seed 1 "$G/table1-$rate-cert.anim.json"
  run "table1-$rate-double" "$G/table1-$rate.anim.json" double --threads 1 &
  run "table1-$rate-double-noplanes" "$G/table1-$rate.anim.json" double --threads 1 --no-planes
  wait
  run "table1-$rate-certified" "$G/table1-$rate-cert.anim.json" certified --threads 1 &
  run "table1-$rate-certified-noplanes" "$G/table1-$rate-cert.anim.json" certified --threads 1 --no-planes
  wait
done
for rate in 0.1 0.5 1; do
  for f in double double-noplanes certified certified-noplanes; do
    [ -s "$G/table1-$rate-$f.json" ] || { echo "run-animation-report: table1-$rate-$f failed" >&2; exit 1; }
  done
done
# table2: the main orbit (radius 5.49) and a grazing one (5.4999999: 1e-7 deep at the ends of the 4.5 axis)
fcl_ok=0
"$E" fcl cases/spheres/spheres-crossing.json --samples 1 >/dev/null 2>&1 && fcl_ok=1
[ "$fcl_ok" = 1 ] || echo "run-animation-report: eccd fcl is not available (FCL not built in): no FCL column" >&2
fcl_frames() {  # VARIANT N: eccd fcl on every frame's scene, one JSON line per frame
  echo "run-animation-report: table2-$1 fcl/sample:$2 on $T2_FRAMES frames" >&2
  for ((k = 0; k < T2_FRAMES; k++)); do
    "$E" fcl "$G/table2-$1-scenes/frame-$k.json" --samples "$2" --json | tr -d '\n'
    echo
  done > "$G/table2-$1-fcl-$2.jsonl"
}
for v in main:5.49 graze:5.4999999; do
  name=${v%%:*} radius=${v#*:}
  python3 "$GEN" table2 --frames "$T2_FRAMES" --radius "$radius" --scenes "$G/table2-$name-scenes" "$G/table2-$name.anim.json"
  run "table2-$name-certified" "$G/table2-$name.anim.json" certified --all-intervals
  run "table2-$name-double" "$G/table2-$name.anim.json" double --all-intervals
  if [ "$fcl_ok" = 1 ]; then
    fcl_frames "$name" 1 &
    fcl_frames "$name" 10
    wait
    for n in 1 10; do
      [ "$(wc -l < "$G/table2-$name-fcl-$n.jsonl")" = "$T2_FRAMES" ] || { echo "run-animation-report: table2-$name fcl/sample:$n failed" >&2; exit 1; }
    done
  fi
done
python3 "$GEN" boxers --frames "$BOX_FRAMES" "$G/boxers.anim.json"
python3 "$GEN" boxers --frames "$BOX_CERT_FRAMES" "$G/boxers-cert.anim.json"
run boxers-double "$G/boxers.anim.json" double
run boxers-certified "$G/boxers-cert.anim.json" certified
# double against certified on the same frames: double on the certified file's frames
if [ "$BOX_CERT_FRAMES" != "$BOX_FRAMES" ]; then run boxers-double-certframes "$G/boxers-cert.anim.json" double; fi
end=$(date +%s)
python3 scripts/animation_report.py "$G" "$OUT" --seconds $((end - start)) \
  --sizes "T1_FRAMES=$T1_FRAMES T1_CERT_FRAMES=$T1_CERT_FRAMES T2_FRAMES=$T2_FRAMES BOX_FRAMES=$BOX_FRAMES BOX_CERT_FRAMES=$BOX_CERT_FRAMES"
echo "run-animation-report: $OUT/report.md ($((end - start)) s)" >&2
