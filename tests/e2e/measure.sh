#!/usr/bin/env bash
# Measures the live mode three times (tests/e2e/measure.mjs) and prints one
# table: frames/s and latency while playing and paused, each stage's median,
# and the machine's load when each run began, under a line naming the CPU
# and the Chromium that measured (a figure is a figure of one machine).
#
#   bash tests/e2e/measure.sh [path/to/epviz] [runs] [job arguments...]
#
# The figures in docs/serve.md come from this. Run it on an otherwise idle
# machine to compare with them; the load column says how idle it was.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=${1:-$here/../../build/epviz}
runs=${2:-3}
shift $(( $# > 2 ? 2 : $# )) || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for i in $(seq 1 "$runs"); do
  cut -d' ' -f1 /proc/loadavg > "$out/load$i"
  echo "run $i of $runs (load $(cat "$out/load$i"))" >&2
  node "$here/measure.mjs" "$binary" "$out/run$i.json" "$@" > "$out/log$i" 2>&1 || {
    cat "$out/log$i" >&2
    exit 1
  }
done
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
chromium=$( (chromium --version || /usr/bin/chromium --version) 2>/dev/null | head -1 || true)
node - "$out" "$runs" "${cpu:-unknown CPU}" "${chromium:-unknown Chromium}" <<'JS'
const fs = require('fs');
const [dir, runs, cpu, chromium] = process.argv.slice(2);
const rows = [];
for (let i = 1; i <= Number(runs); ++i) {
  const r = JSON.parse(fs.readFileSync(`${dir}/run${i}.json`, 'utf8'));
  r.load = fs.readFileSync(`${dir}/load${i}`, 'utf8').trim();
  rows.push(r);
}
const s = (r, k) => (r.stages[k] === null ? '-' : r.stages[k]);
console.log(`view ${rows[0].width}x${rows[0].height}, ${rows[0].mime}, ${new Date().toISOString()}, ${require('os').cpus().length} cores`);
console.log(`CPU: ${cpu}; browser: ${chromium}`);
console.log('| run | load | frames/s | latency median (p90) ms | paused median (p90) ms | size playing | simulate | draw | read back | encode | queue | send | decode | paint | kB | decode alone (size) |');
console.log('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|');
rows.forEach((r, i) => {
  console.log(`| ${i + 1} | ${r.load} | ${r.fps} | ${r.latency_median_ms} (${r.latency_p90_ms}) | ` +
    `${r.paused_latency_median_ms} (${r.paused_latency_p90_ms}) | ${r.playing_size} | ${s(r, 'simulate_ms')} | ${s(r, 'draw_ms')} | ` +
    `${s(r, 'read_back_ms')} | ${s(r, 'encode_ms')} | ${s(r, 'queue_ms')} | ${s(r, 'send_ms')} | ` +
    `${s(r, 'decode_ms')} | ${s(r, 'paint_ms')} | ${r.stages.bytes === null ? '-' : Math.round(r.stages.bytes / 1000)} | ` +
    `${r.decode_alone.ms} (${r.decode_alone.size}) |`);
});
JS
