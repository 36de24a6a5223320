#!/usr/bin/env bash
# The three paper reproductions on animations (000 Tables 1-2, 001 section 5), into
# reports/animation/: report.md (each figure next to the paper's) and
# summary.json (what it was made from). The animation files and the full
# `eccd animate --json` answers go to reports/animation/generated/ (not
# committed; written again on every run).
#  (a) paper 000 Table 1: two ellipsoids 3,3,5, centres 8 apart, 0.1, 0.5, 1 rad per frame, with and without planes;
#  (b) paper 000 Table 2: a sphere orbiting an ellipsoid 4.5,4,2; certified against FCL (eccd fcl) per frame;
#  (c) paper 001 section 5 in spirit: two figures of 24 ellipsoids, 576 pairs per frame, double and certified.
# Sizes (environment): T1_FRAMES (default 10000), T2_FRAMES (default 629: one orbit), BOX_FRAMES (1000), and the
# certified runs' T1_CERT_FRAMES and BOX_CERT_FRAMES. By default (FULL=1) every run has the papers' sizes, certified
# too (T1_CERT_FRAMES=T1_FRAMES, BOX_CERT_FRAMES=BOX_FRAMES unless set): 149 s on 2 cores since 3D certified mode
# decides by the interval Bezier proof (without it, about 40 min). FULL=0: certified on 1000 Table 1 frames
# and 200 boxers frames only (a quicker trial). report.md states which sizes were run.
# GJK_TIGHT (default 1e-12): FCL's tight gjk_tolerance for Table 2 (`eccd fcl --gjk-tolerance`), next to
# FCL's default (1e-6).
# Both cores: single-pair runs go two at a time (with/without planes; certified and double), the boxers run with
# --jobs 2 (THREADS); per-frame times are each run's own thread time. Progress of every run on stderr, each
# line prefixed with the run's name (QUIET=1: none).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/eccd ] || bash scripts/bootstrap.sh
E=build/eccd
OUT=${OUT:-reports/animation}  # OUT=DIR: somewhere else (a trial run at small sizes)
G=$OUT/generated
FULL=${FULL:-1}
T1_FRAMES=${T1_FRAMES:-10000}
T2_FRAMES=${T2_FRAMES:-629}
BOX_FRAMES=${BOX_FRAMES:-1000}
if [ "$FULL" = 1 ]; then
  T1_CERT_FRAMES=${T1_CERT_FRAMES:-$T1_FRAMES}
  BOX_CERT_FRAMES=${BOX_CERT_FRAMES:-$BOX_FRAMES}
else
  T1_CERT_FRAMES=${T1_CERT_FRAMES:-1000}
  BOX_CERT_FRAMES=${BOX_CERT_FRAMES:-200}
fi
GJK_TIGHT=${GJK_TIGHT:-1e-12}
THREADS=${THREADS:-2}
QUIET=${QUIET:-0}
for v in T1_FRAMES T1_CERT_FRAMES T2_FRAMES BOX_FRAMES BOX_CERT_FRAMES THREADS; do
  case ${!v} in '' | *[!0-9]* | 0) echo "run-animation-report: $v=${!v}: expected a positive integer" >&2; exit 2 ;; esac
done
GEN=cases/animations/make_repro.py
rm -rf "$G"
mkdir -p "$G"
start=$(date +%s)
run() {  # name file arith [extra...]: eccd animate, its progress on stderr prefixed with the name
  local name=$1 file=$2 arith=$3
  shift 3
  echo "run-animation-report: $name ($arith $*) started after $(($(date +%s) - start)) s" >&2
  if [ "$QUIET" = 1 ]; then
    "$E" animate "$file" --arith "$arith" --json --quiet "$@" --out "$G/$name.json"
  else
    "$E" animate "$file" --arith "$arith" --json "$@" --out "$G/$name.json" 2> >(sed -u "s/^/[$name] /" >&2)
  fi
  echo "run-animation-report: $name done after $(($(date +%s) - start)) s" >&2
}
for rate in 0.1 0.5 1; do
  python3 "$GEN" table1 --rate "$rate" --frames "$T1_FRAMES" --seed 1 "$G/table1-$rate.anim.json"
  python3 "$GEN" table1 --rate "$rate" --frames "$T1_CERT_FRAMES" --seed 1 "$G/table1-$rate-cert.anim.json"
  run "table1-$rate-double" "$G/table1-$rate.anim.json" double --jobs 1 &
  run "table1-$rate-double-noplanes" "$G/table1-$rate.anim.json" double --jobs 1 --no-planes
  wait
  run "table1-$rate-certified" "$G/table1-$rate-cert.anim.json" certified --jobs 1 &
  run "table1-$rate-certified-noplanes" "$G/table1-$rate-cert.anim.json" certified --jobs 1 --no-planes
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
fcl_frames() {  # VARIANT N [TOL]: eccd fcl on every frame's scene, one JSON line per frame; TOL: --gjk-tolerance
  local out="$G/table2-$1-fcl-$2${3:+-tight}.jsonl"
  echo "run-animation-report: table2-$1 fcl/sample:$2 ${3:+gjk_tolerance $3 }on $T2_FRAMES frames" >&2
  for ((k = 0; k < T2_FRAMES; k++)); do
    "$E" fcl "$G/table2-$1-scenes/frame-$k.json" --samples "$2" ${3:+--gjk-tolerance "$3"} --json | tr -d '\n'
    echo
  done > "$out"
  [ "$(wc -l < "$out")" = "$T2_FRAMES" ] || { echo "run-animation-report: $out: not one line per frame" >&2; exit 1; }
}
for v in main:5.49 graze:5.4999999; do
  name=${v%%:*} radius=${v#*:}
  python3 "$GEN" table2 --frames "$T2_FRAMES" --radius "$radius" --scenes "$G/table2-$name-scenes" "$G/table2-$name.anim.json"
  run "table2-$name-certified" "$G/table2-$name.anim.json" certified --all-intervals --jobs 1 &
  run "table2-$name-double" "$G/table2-$name.anim.json" double --all-intervals --jobs 1
  wait
  for f in certified double; do
    [ -s "$G/table2-$name-$f.json" ] || { echo "run-animation-report: table2-$name-$f failed" >&2; exit 1; }
  done
  if [ "$fcl_ok" = 1 ]; then
    # FCL's default gjk_tolerance (1e-6) and the tight one, side by side
    fcl_frames "$name" 1 &
    fcl_frames "$name" 10
    wait
    fcl_frames "$name" 1 "$GJK_TIGHT" &
    fcl_frames "$name" 10 "$GJK_TIGHT"
    wait
    for f in 1 10 1-tight 10-tight; do  # a background fcl_frames that failed left a short file
      [ "$(wc -l < "$G/table2-$name-fcl-$f.jsonl")" = "$T2_FRAMES" ] || { echo "run-animation-report: table2-$name fcl $f failed" >&2; exit 1; }
    done
  fi
done
python3 "$GEN" boxers --frames "$BOX_FRAMES" "$G/boxers.anim.json"
python3 "$GEN" boxers --frames "$BOX_CERT_FRAMES" "$G/boxers-cert.anim.json"
run boxers-double "$G/boxers.anim.json" double --jobs "$THREADS"
run boxers-certified "$G/boxers-cert.anim.json" certified --jobs "$THREADS"
# double against certified on the same frames: double on the certified file's frames
if [ "$BOX_CERT_FRAMES" != "$BOX_FRAMES" ]; then run boxers-double-certframes "$G/boxers-cert.anim.json" double --jobs "$THREADS"; fi
# the same motion sampled 4 times as finely (double): how the kept plane's share depends on the motion per frame
python3 "$GEN" boxers --frames "$BOX_FRAMES" --subdivide 4 "$G/boxers-sub4.anim.json"
run boxers-sub4-double "$G/boxers-sub4.anim.json" double --jobs "$THREADS"
end=$(date +%s)
python3 scripts/animation_report.py "$G" "$OUT" --seconds $((end - start)) \
  --sizes "T1_FRAMES=$T1_FRAMES T1_CERT_FRAMES=$T1_CERT_FRAMES T2_FRAMES=$T2_FRAMES BOX_FRAMES=$BOX_FRAMES BOX_CERT_FRAMES=$BOX_CERT_FRAMES" \
  --full "$FULL" --gjk-tight "$GJK_TIGHT"
echo "run-animation-report: $OUT/report.md ($((end - start)) s)" >&2
