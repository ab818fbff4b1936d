#!/usr/bin/env bash
# `epviz sweep` points per second on the shipped chaos map cut to 32 x 32 =
# 1,024 points (T = 100, FTLE in windows of 0.5), on each instruction set of
# this CPU (EPVIZ_SIMD) with 1 and 2 threads, and, when BASELINE names an
# epviz built before sweeps used the batch path, that binary too. Every run's
# rows must equal the first's but for the CPU time; the figures go to
# docs/ensembles.md.
#
#   bench/sweep/batch_sweep.sh [build/epviz]        (BASELINE=/path/to/old/epviz)
set -euo pipefail

here=$(cd "$(dirname "$0")/../.." && pwd)
epviz=${1:-$here/build/epviz}
[[ -x $epviz ]] || { echo "batch_sweep.sh: $epviz: no epviz executable (build it first)" >&2; exit 2; }
if [[ -n ${BASELINE:-} && ! -x $BASELINE ]]; then
  echo "batch_sweep.sh: BASELINE=$BASELINE: not an executable" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$here/render_jobs/chaos_map.sweep.json" "$work/chaos_1024.sweep.json" <<'EOF'
import json, sys
spec = json.load(open(sys.argv[1]))
for axis in spec["axes"][:2]:
    axis["count"] = 32
spec.pop("atlas", None)
json.dump(spec, open(sys.argv[2], "w"))
EOF

paths=()
for p in scalar sse2 avx2 avx512; do
  if EPVIZ_SIMD=$p "$epviz" --version 2>/dev/null | grep -q "batch SIMD path: $p"; then paths+=("$p"); fi
done

echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')  cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)  cores: $(nproc)"
echo "flags: $(grep -m1 flags /proc/cpuinfo | tr ' ' '\n' | grep -E '^(sse2|avx|avx2|fma|avx512f|avx512dq)$' | xargs)"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# points/s: per second of wall time; points/cpu-s: per second of CPU time of
# all the process's threads (what other load on the machine disturbs least).
printf '%-22s %7s %8s %8s %9s %12s\n' run threads wall_s cpu_s points/s points/cpu-s

first=""
run() {  # label threads binary [env...]
  local label=$1 threads=$2 bin=$3
  shift 3
  local out="$work/$label.jsonl"
  /usr/bin/time -f '%e %U %S' -o "$work/time" env "$@" "$bin" sweep \
    "$work/chaos_1024.sweep.json" --out "$out" --jobs "$threads" --quiet >/dev/null
  python3 - "$label" "$threads" "$work/time" "$out" "${first:-$out}" <<'EOF'
import json, sys
label, threads, timing, out, ref = sys.argv[1:]
def rows(path):
    r = {}
    for line in open(path):
        row = json.loads(line)
        row.pop("cpu_seconds")
        r[row["index"]] = row
    return r
mine = rows(out)
assert len(mine) == 1024, f"{label}: {len(mine)} rows"
assert mine == rows(ref), f"{label}: rows differ from the first run's"
wall, user, system = map(float, open(timing).read().split()[-3:])
cpu = user + system
print(f"{label:<22} {threads:>7} {wall:8.2f} {cpu:8.2f} {1024 / wall:9.1f} {1024 / cpu:12.1f}")
EOF
  first=${first:-$out}
}

for threads in 1 2; do
  for p in "${paths[@]}"; do run "batch-$p-j$threads" "$threads" "$epviz" EPVIZ_SIMD="$p"; done
  if [[ -n ${BASELINE:-} ]]; then run "baseline-j$threads" "$threads" "$BASELINE"; fi
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
