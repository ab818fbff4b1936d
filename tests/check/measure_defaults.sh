#!/bin/sh
# Measures what `epviz check` sees for run-to-run noise and for changes a
# person would notice; the table in docs/ci.md comes from this.
#   tests/check/measure_defaults.sh build/epviz render_jobs/kovalevskaya.json [WIDTHxHEIGHT]
# Prints, per variant: the share of pixels differing at all (threshold 0), at
# the default threshold, and the SSIM, for each checked frame.
set -eu
epviz=$(realpath "$1")
job=$(realpath "$2")
size=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# variant NAME JQ-LIKE-PYTHON-EDIT: writes $work/NAME/<stem>.json
stem=$(basename "$job" .json)
variant() {
  mkdir -p "$work/$1"
  /usr/bin/python3 - "$job" "$work/$1/$stem.json" "$size" "$2" <<'PY'
import json, sys
src, dst, size, edit = sys.argv[1:5]
j = json.load(open(src))
if size:
    w, h = size.split('x'); j['width'], j['height'] = int(w), int(h)
j['output'] = {'dir': 'out', 'format': 'png'}
exec(edit)
json.dump(j, open(dst, 'w'), indent=1)
PY
}

variant base "pass"
variant camera_2deg "j.setdefault('camera', {})['azimuth'] = 35.0 + 2"
variant colour_strong "j.setdefault('colours', {})['body'] = '#5c9ecc'"
variant colour_subtle "j.setdefault('colours', {})['body'] = '#c09050'"
variant trail_plus_1s "j['trail']['length'] = j['trail']['length'] + 1.0"
variant method_rk4 "j['simulation']['method'] = 'rk4'"

"$epviz" check "$work/base/$stem.json" --golden "$work/golden" --update >/dev/null
pixels() {  # threshold, job, env: the share of pixels over the threshold, per frame
  env $3 "$epviz" check "$2" --golden "$work/golden" --threshold "$1" --max-differing 100 2>/dev/null |
    grep -o '[0-9.e-]* % pixels' | cut -d' ' -f1 | paste -sd/
}
measure() {  # label, job, env
  ss=$(env $3 "$epviz" check "$2" --golden "$work/golden" --metric ssim --threshold 0.0001 2>/dev/null |
    grep -o 'SSIM [0-9.]*' | cut -d' ' -f2 | paste -sd/)
  printf '| %s | %s | %s | %s | %s |\n' "$1" "$(pixels 0 "$2" "$3")" "$(pixels 1 "$2" "$3")" "$(pixels 4 "$2" "$3")" "$ss"
}
echo "| variant | % pixels differing at all | % over 1/255 | % over 4/255 | SSIM |"
echo "|---|---|---|---|---|"
for run in $(seq 1 "${RUNS:-3}"); do
  measure "same job, LP_NUM_THREADS=1, run $run" "$work/base/$stem.json" LP_NUM_THREADS=1
  measure "same job, LP_NUM_THREADS=2, run $run" "$work/base/$stem.json" LP_NUM_THREADS=2
done
measure "same job, llvmpipe 128-bit vectors" "$work/base/$stem.json" LP_NATIVE_VECTOR_WIDTH=128
measure "same job, softpipe (another rasteriser)" "$work/base/$stem.json" GALLIUM_DRIVER=softpipe
for v in camera_2deg colour_strong colour_subtle trail_plus_1s method_rk4; do
  measure "$v" "$work/$v/$stem.json" X=1
done
