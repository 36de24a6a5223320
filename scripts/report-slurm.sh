#!/usr/bin/env bash
# `eccd report` as a Slurm job array: task i of N runs `eccd report --shard i/N`
# into its own folder, and a job that starts when every task has succeeded
# (--dependency=afterok) joins the parts with `eccd report --merge`.
#
# Usage (on the cluster's login node, in a checkout whose build/eccd is built,
# in a folder every node sees):
#   scripts/report-slurm.sh submit N OUT [eccd report options...]
# submits the array (tasks 0..N-1) and the merge job, and prints their job ids.
# The script submits itself; Slurm runs it as
#   report-slurm.sh task  N OUT OPTIONS   (one array task: SLURM_ARRAY_TASK_ID = i)
#   report-slurm.sh merge N OUT OPTIONS   (the merge: OUT from OUT.parts/shard-0..N-1)
# Each task uses SLURM_CPUS_PER_TASK worker processes (--jobs). Resources: set
# SBATCH_OPTS, e.g. SBATCH_OPTS="--partition=short --time=02:00:00 --cpus-per-task=8".
# The options (plan, --seed, --mpfr-bits, --budget, ...) go to every task and must be
# the same for all of them (--merge checks); --no-figures goes to the merge too.
# Environment: ECCD (the eccd binary; default build/eccd of this checkout, else
# eccd on PATH), SBATCH_OPTS (more sbatch options for both jobs).
# Logs: OUT.parts/slurm-JOB_TASK.log. Exit status: eccd's; 2 for bad usage.
#SBATCH --job-name=eccd-report
set -euo pipefail
usage() {
  echo "usage: $0 submit N OUT [eccd report options...]   (N: number of array tasks = shards)" >&2
  exit 2
}
[ $# -ge 3 ] || usage
mode=$1 n=$2 out=$3
shift 3
[[ $n =~ ^[1-9][0-9]*$ ]] || usage
self=$(readlink -f "$0")
here=$(cd "$(dirname "$self")/.." && pwd)
eccd=${ECCD:-}
if [ -z "$eccd" ]; then
  if [ -x "$here/build/eccd" ]; then eccd=$here/build/eccd; else eccd=eccd; fi
fi
parts="$out.parts"
case "$mode" in
  submit)
    command -v sbatch >/dev/null 2>&1 || { echo "$0: sbatch not found (is this a Slurm login node?)" >&2; exit 2; }
    mkdir -p "$parts"
    export ECCD="$eccd"
    # shellcheck disable=SC2086  # SBATCH_OPTS is a list of options
    array=$(sbatch --parsable --export=ALL --array="0-$((n - 1))" --output="$parts/slurm-%A_%a.log" ${SBATCH_OPTS:-} \
      "$self" task "$n" "$out" "$@")
    array=${array%%;*}
    # shellcheck disable=SC2086
    merge=$(sbatch --parsable --export=ALL --dependency="afterok:$array" --output="$parts/slurm-%j-merge.log" ${SBATCH_OPTS:-} \
      "$self" merge "$n" "$out" "$@")
    echo "array job $array (tasks 0-$((n - 1))), merge job ${merge%%;*} -> $out"
    ;;
  task)
    i=${SLURM_ARRAY_TASK_ID:?"task mode runs inside a Slurm array task (SLURM_ARRAY_TASK_ID unset)"}
    exec "$eccd" report --shard "$i/$n" --jobs "${SLURM_CPUS_PER_TASK:-1}" --out-dir "$parts/shard-$i" "$@"
    ;;
  merge)
    merge_opts=()
    for o in "$@"; do [ "$o" = --no-figures ] && merge_opts+=(--no-figures); done
    shards=()
    for ((i = 0; i < n; ++i)); do shards+=("$parts/shard-$i"); done
    exec "$eccd" report --merge "${shards[@]}" --out-dir "$out" "${merge_opts[@]}"
    ;;
  *) usage ;;
esac
