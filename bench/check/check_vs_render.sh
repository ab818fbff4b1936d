#!/usr/bin/env bash
# Is `epviz check -j 2` limited by rendering or by comparing? Checks 100
# frames (50 of each of two 1280x720 jobs, two jobs at once) against goldens
# made for the purpose, and renders the same 100 frames to PNG with two
# `epviz render` processes at once; the check's extra time over the render is
# what comparing (and reading the goldens) costs. Each is run three times,
# interleaved, and the medians are printed with the load.
#
#   bash bench/check/check_vs_render.sh [path/to/epviz]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
epviz=$(realpath "${1:-$here/../../build/epviz}")
jobs=("$here/../../render_jobs/kovalevskaya.json" "$here/../../render_jobs/lagrange.json")
frames=0:49
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$epviz" check "${jobs[@]}" --frames "$frames" --golden "$work/golden" --update -j 2 >/dev/null

seconds() { # command... -> wall seconds on stdout
  local s e
  s=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  e=$(date +%s.%N)
  echo "$e - $s" | bc
}
render_both() {
  "$epviz" render "${jobs[0]}" --frames "$frames" --format png --out "$work/r0" --quiet &
  "$epviz" render "${jobs[1]}" --frames "$frames" --format png --out "$work/r1" --quiet &
  wait
}
check_both() { "$epviz" check "${jobs[@]}" --frames "$frames" --golden "$work/golden" -j 2 "$@"; }

declare -a render pixel ssim
for i in 1 2 3; do
  render+=("$(seconds render_both)")
  pixel+=("$(seconds check_both)")
  ssim+=("$(seconds check_both --metric ssim)")
done
median() { printf '%s\n' "$@" | sort -n | sed -n 2p; }
r=$(median "${render[@]}")
p=$(median "${pixel[@]}")
s=$(median "${ssim[@]}")
echo "100 frames at 1280x720, two jobs at once, medians of 3 (load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%F))"
printf '| render to PNG | %.2f s |\n' "$r"
printf '| check, pixel metric | %.2f s (%.2fx the render) |\n' "$p" "$(echo "$p / $r" | bc -l)"
printf '| check, SSIM | %.2f s (%.2fx the render) |\n' "$s" "$(echo "$s / $r" | bc -l)"
