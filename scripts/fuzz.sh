#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang in their own build
# directory and runs each for a bounded time, starting from its committed
# corpus (fuzz/corpus/<target>/); exits 1 if any target finds a crash, a
# sanitizer report, a timeout or an out-of-memory. A crashing input is kept
# in the build directory's artifacts/ folder: add it to a regression test.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# SECONDS per target (default 60); TARGETs default to all. Environment:
# EPVIZ_FUZZ_BUILD (build directory, default build-fuzz), EPVIZ_FUZZ_JOBS
# (parallel compiles, default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift $(($# > 0 ? 1 : 0))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_job_reader fuzz_simulate_options fuzz_protocol fuzz_sweep_reader)
build=${EPVIZ_FUZZ_BUILD:-$root/build-fuzz}

# The largest input each target is tried with: a job file can be long (and
# deep nesting needs room), a page message is at most the server's 64 KiB.
max_len() {
  case "$1" in
    fuzz_job_reader) echo 65536 ;;
    fuzz_sweep_reader) echo 65536 ;;
    fuzz_simulate_options) echo 4096 ;;
    fuzz_protocol) echo 65536 ;;
    *) echo 4096 ;;
  esac
}

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Only what the targets need: no renderer, tests or benchmarks.
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DEPVIZ_BUILD_FUZZ=ON -DEPVIZ_BUILD_RENDER=OFF -DEPVIZ_BUILD_TESTS=OFF \
  -DEPVIZ_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
ninja -C "$build" -j"${EPVIZ_FUZZ_JOBS:-2}" "${targets[@]}"

mkdir -p "$build/artifacts"
failed=()
for t in "${targets[@]}"; do
  # New inputs the fuzzer finds go to a scratch corpus, not into the committed one.
  scratch=$(mktemp -d)
  echo "fuzz: $t for ${seconds} s"
  if ! "$build/fuzz/$t" -max_total_time="$seconds" -max_len="$(max_len "$t")" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
    "$scratch" "$root/fuzz/corpus/$t" 2>"$build/$t.log"; then
    failed+=("$t")
    tail -n 40 "$build/$t.log" >&2
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$build/$t.log" | sed "s/^/  $t /" || true
  rm -rf "$scratch"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (inputs in $build/artifacts/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds} s each without a finding"
