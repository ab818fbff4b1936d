#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang and runs each for a bounded
# time, two at a time (one per core), starting from its committed corpus
# (fuzz/corpus/<target>/); exits 1 if any target finds a crash, a sanitizer
# report, a timeout or an out-of-memory. A crashing input is kept in the build
# directory's artifacts/ folder: add it to a regression test.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# SECONDS per target (default 60); TARGETs default to all. Environment:
# EPVIZ_FUZZ_BUILD (build directory, default build-fuzz: configured with only
# what the targets need; a directory already configured with
# EPVIZ_BUILD_FUZZ=ON, such as the sanitizer pass's build-asan, is used as it
# is), EPVIZ_FUZZ_JOBS (parallel compiles and fuzzers, default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift $(($# > 0 ? 1 : 0))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_job_reader fuzz_simulate_options fuzz_protocol fuzz_sweep_reader
  fuzz_manifest_reader fuzz_golden_reader fuzz_section_reader fuzz_json_text)
build=${EPVIZ_FUZZ_BUILD:-$root/build-fuzz}

# The largest input each target is tried with: a job file can be long (and
# deep nesting needs room; so can a section file's list of states), a page
# message is at most the server's 64 KiB.
max_len() {
  case "$1" in
    fuzz_job_reader) echo 65536 ;;
    fuzz_sweep_reader) echo 65536 ;;
    fuzz_simulate_options) echo 4096 ;;
    fuzz_protocol) echo 65536 ;;
    fuzz_manifest_reader) echo 16384 ;;
    fuzz_golden_reader) echo 16384 ;;
    fuzz_section_reader) echo 65536 ;;
    *) echo 4096 ;;
  esac
}

# The time one input may take: the documents fuzz_json_text grows (up to 2 MB
# of JSON) are read in a fraction of a second unless reading is slower than
# linear, which is what it looks for.
input_timeout() {
  case "$1" in
    fuzz_json_text) echo 2 ;;
    *) echo 10 ;;
  esac
}

jobs=${EPVIZ_FUZZ_JOBS:-2}
if ! grep -qs '^EPVIZ_BUILD_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Only what the targets need: no renderer, tests or benchmarks.
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DEPVIZ_BUILD_FUZZ=ON -DEPVIZ_BUILD_RENDER=OFF -DEPVIZ_BUILD_TESTS=OFF \
    -DEPVIZ_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
fi
ninja -C "$build" -j"$jobs" "${targets[@]}"

mkdir -p "$build/artifacts"
# One target's run; its log in $build/<target>.log, its status as the exit code.
fuzz_one() {
  local t=$1 scratch
  # New inputs the fuzzer finds go to a scratch corpus, not into the committed one.
  scratch=$(mktemp -d)
  local status=0
  "$build/fuzz/$t" -max_total_time="$seconds" -max_len="$(max_len "$t")" -timeout="$(input_timeout "$t")" \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
    "$scratch" "$root/fuzz/corpus/$t" 2>"$build/$t.log" || status=$?
  rm -rf "$scratch"
  return $status
}

failed=()
pids=()
names=()
# Waits for the oldest running target and reports it.
reap() {
  local t=${names[0]} status=0
  wait "${pids[0]}" || status=$?
  pids=("${pids[@]:1}")
  names=("${names[@]:1}")
  if [ "$status" -ne 0 ]; then
    failed+=("$t")
    tail -n 40 "$build/$t.log" >&2
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$build/$t.log" | sed "s/^/  $t /" || true
}
for t in "${targets[@]}"; do
  [ ${#pids[@]} -lt "$jobs" ] || reap
  echo "fuzz: $t for ${seconds} s"
  fuzz_one "$t" &
  pids+=($!)
  names+=("$t")
done
while [ ${#pids[@]} -gt 0 ]; do reap; done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (inputs in $build/artifacts/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds} s each without a finding"
