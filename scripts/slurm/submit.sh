#!/bin/bash
# Submits a sharded sweep or render as a Slurm job array and the merge that
# runs once every task has ended, whether it succeeded or not
# (--dependency=afterany): the merge names what is missing and, with
# --resubmit, writes OUTDIR/resubmit.sh, which submits again only the failed
# shards and then the merge. Prints the two job ids, array first (on stderr,
# what to do when a task fails).
#
#   scripts/slurm/submit.sh sweep render_jobs/chaos_map.sweep.json results/ 8
#   scripts/slurm/submit.sh render render_jobs/generic.json frames/ 4 --format mp4
#
# Options after SHARDS go to epviz sweep|render; MERGE_ARGS (environment) to
# epviz merge; SBATCH_ARGS to both sbatch calls (e.g. "--partition=short").
# EPVIZ (the binary) is passed on to the jobs with the rest of the environment.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [ $# -lt 4 ] || { [ "$1" != sweep ] && [ "$1" != render ]; }; then
  echo "usage: $0 sweep|render FILE OUTDIR SHARDS [options for epviz sweep|render]" >&2
  exit 2
fi
kind=$1 file=$2 out=$3 shards=$4
shift 4
case $shards in
  '' | *[!0-9]* | 0) echo "$0: SHARDS: expected a positive whole number, got '$shards'" >&2; exit 2 ;;
esac
mkdir -p "$out"
# shellcheck disable=SC2086  # SBATCH_ARGS is a list of options
array=$(sbatch --parsable ${SBATCH_ARGS:-} --array=0-$((shards - 1)) --chdir="$PWD" \
  "$here/$kind.sbatch" "$file" "$out" "$@")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_ARGS:-} --dependency=afterany:"$array" --chdir="$PWD" \
  "$here/merge.sbatch" "$out" --resubmit "$out/resubmit.sh" ${MERGE_ARGS:-})
merge=${merge%%;*}
echo "$array $merge"
echo "$0: if a task fails, merge job $merge names its shard (epviz-merge-$merge.log) and" \
  "writes $out/resubmit.sh; bash $out/resubmit.sh then runs sbatch --array=<the failed indices>" \
  "and the merge again" >&2
