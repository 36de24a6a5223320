#!/usr/bin/env bash
# `eccd report` split into N shards run by GNU parallel, then joined by --merge.
#
# Usage: scripts/report-parallel.sh N OUT [eccd report options...]
#   N     number of shards (each runs `eccd report --shard i/N` with one worker process)
#   OUT   the joined report's folder; the shards' parts go to OUT.parts/shard-i
#   The options (plan, --seed, --mpfr-bits, --budget, ...) go to every shard; they must be the
#   same for all of them (--merge checks). --no-figures is passed on to the merge as well.
# Environment: ECCD (the eccd binary; default build/eccd of this checkout, else eccd on
#   PATH), JOBS (parallel jobs at once; default: N), PARALLEL_OPTS (more options for GNU
#   parallel, e.g. "--sshloginfile nodes.txt" to spread the shards over machines that
#   share this folder).
# The one-liner it runs (docs/sweeps.md):
#   seq 0 $((N-1)) | parallel -j N "$ECCD" report --shard {}/N --jobs 1 --out-dir OUT.parts/shard-{} OPTIONS
#   "$ECCD" report --merge OUT.parts/shard-* --out-dir OUT
# Exit status: that of the first shard that failed, else that of the merge; 2 for bad usage.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -lt 2 ] || ! [[ $1 =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 N OUT [eccd report options...]   (N: number of shards, a positive integer)" >&2
  exit 2
fi
n=$1 out=$2
shift 2
if ! command -v parallel >/dev/null 2>&1; then
  echo "$0: GNU parallel is not installed (Debian: apt-get install parallel)" >&2
  exit 2
fi
eccd=${ECCD:-}
if [ -z "$eccd" ]; then
  if [ -x "$here/build/eccd" ]; then eccd=$here/build/eccd; else eccd=eccd; fi
fi
merge_opts=()
for o in "$@"; do [ "$o" = --no-figures ] && merge_opts+=(--no-figures); done
parts="$out.parts"
mkdir -p "$parts"
# --quote: the arguments reach eccd as given (an empty one, spaces); --halt now,fail=1: the first
# failing shard stops the others, and its exit status is ours.
# shellcheck disable=SC2086  # PARALLEL_OPTS is a list of options
seq 0 $((n - 1)) | parallel --will-cite --quote --halt now,fail=1 -j "${JOBS:-$n}" ${PARALLEL_OPTS:-} \
  "$eccd" report --shard "{}/$n" --jobs 1 --out-dir "$parts/shard-{}" "$@"
shards=()
for ((i = 0; i < n; ++i)); do shards+=("$parts/shard-$i"); done
"$eccd" report --merge "${shards[@]}" --out-dir "$out" "${merge_opts[@]}"
