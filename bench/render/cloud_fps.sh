#!/usr/bin/env bash
# Frames per second of the shipped cloud job (render_jobs/cloud_generic.json:
# 10,000 members, 360 frames at 1280x720) rendered end to end by `epviz
# render`, with its cloud and without it (the same job less its "cloud" key),
# to MP4 and to PNG frames, REPS times each, interleaved. Each line gives the
# frames/s epviz reports (the frames, from the first drawn to the video
# finished; the members' integration before them is not counted), the wall
# and CPU seconds of the whole command (integration, ffmpeg included) and
# the load average before it: the target is 30 frames/s, and on a shared
# machine only the load says what a figure means. The render-only cost (frames
# drawn and read back, nothing encoded) is build/bench/epviz_render_bench
# --benchmark_filter=cloud. The figures go to docs/ensembles.md (The cloud).
#
#   bench/render/cloud_fps.sh [build/epviz]        (REPS=3, FORMATS="mp4 png")
set -euo pipefail

here=$(cd "$(dirname "$0")/../.." && pwd)
epviz=${1:-$here/build/epviz}
[[ -x $epviz ]] || { echo "cloud_fps.sh: $epviz: no epviz executable (build it first)" >&2; exit 2; }
reps=${REPS:-3}
[[ $reps =~ ^[1-9][0-9]*$ ]] || { echo "cloud_fps.sh: REPS=$reps: not a positive whole number" >&2; exit 2; }
formats=${FORMATS:-mp4 png}
for f in $formats; do
  [[ $f == mp4 || $f == png ]] || { echo "cloud_fps.sh: FORMATS: '$f' is not mp4 or png" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

job=$here/render_jobs/cloud_generic.json
python3 - "$job" "$work/no_cloud.json" <<'PY'
import json, sys
job = json.load(open(sys.argv[1]))
del job["cloud"]
json.dump(job, open(sys.argv[2], "w"))
PY

echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')  cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)  cores: $(nproc)  LP_NUM_THREADS=${LP_NUM_THREADS:-default}"
printf '%-8s %-4s %8s %8s %8s %6s\n' cloud fmt frames/s wall_s cpu_s load
for ((r = 0; r < reps; ++r)); do
  for fmt in $formats; do
    for which in with without; do
      file=$job
      [[ $which == without ]] && file=$work/no_cloud.json
      rm -rf "$work/out"
      load=$(cut -d' ' -f1 /proc/loadavg)
      # GNU time's %e %U %S: wall, user and system seconds, ffmpeg's included.
      out=$( { /usr/bin/time -f 'time %e %U %S' "$epviz" render "$file" --format "$fmt" \
                 --out "$work/out" --quiet; } 2>&1) || { echo "$out" >&2; exit 1; }
      fps=$(sed -n 's/.*(\([0-9.]*\) frames\/s).*/\1/p' <<<"$out")
      read -r wall user sys < <(sed -n 's/^time //p' <<<"$out")
      printf '%-8s %-4s %8s %8s %8.1f %6s\n' "$which" "$fmt" "$fps" "$wall" \
        "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" "$load"
    done
  done
done
