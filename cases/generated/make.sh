#!/bin/sh
# Regenerates the regression corpus cases/generated/ exactly: seeded scenes from
# `eccd generate` (compare/scene_generator.hpp) with the exact pipeline's answer
# stored in each file (--answer). See README.md next to this script.
#
#   cases/generated/make.sh [PATH/TO/eccd]     (default: build/eccd of this checkout)
#
# The three folders are rebuilt in a temporary folder and swapped in only when
# every generate command has succeeded. Takes about 30 s (the exact answers).
set -eu

HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
EXE=${1:-$ROOT/build/eccd}
case "$EXE" in /*) ;; *) EXE="$(pwd)/$EXE" ;; esac
[ -x "$EXE" ] || { echo "make.sh: $EXE is not an executable (pass the path of eccd)" >&2; exit 2; }

SEED=1  # the run seed; each scene's seed derives from it and its combination (in the file name and note)
TMP=$(mktemp -d "$HERE/.make.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

gen() { "$EXE" generate --seed "$SEED" --answer --force "$@"; }

# 2D, kinematic motions: degrees 2..6 x colliding, free, touch, near-miss at d = 1e-4 and 1e-10; 2 scenes each.
gen --out "$TMP/2d" --dims 2 --degrees 2,3,4,5,6 --families colliding,free,touch,near-miss --separations 4,10 --count 2

# 3D, euler motions: degrees 2..6 x colliding, free, touch (2 each) and near-miss at 1e-4 and 1e-10 (1 each).
gen --out "$TMP/3d-euler" --dims 3 --motions euler --degrees 2,3,4,5,6 --families colliding,free,touch --count 2
gen --out "$TMP/3d-euler" --dims 3 --motions euler --degrees 2,3,4,5,6 --families near-miss --separations 4,10 --count 1

# 3D, affine motions (near-miss does not apply): degrees 2..6 x free, touch; colliding only up to degree 4
# (the exact pipeline takes about 3-5 s per colliding affine scene of degree 5 or 6).
gen --out "$TMP/3d-affine" --dims 3 --motions affine --degrees 2,3,4,5,6 --families free,touch --count 1
gen --out "$TMP/3d-affine" --dims 3 --motions affine --degrees 2,3,4 --families colliding --count 1

for d in 2d 3d-euler 3d-affine; do
  rm -rf "${HERE:?}/$d"
  mv "$TMP/$d" "$HERE/$d"
done
echo "cases/generated: $(find "$HERE" -name '*.json' | wc -l) scene(s)"
