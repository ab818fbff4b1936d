#!/usr/bin/env bash
# The README's second command (and CI's): set up, build and run the whole test
# suite, then build it again under the sanitizers and run it there, and fuzz
# the parsers of untrusted input.
#
#   EPVIZ_SANITIZERS=all|asan|tsan|none   which sanitizer passes (default all)
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage says when it ended, so that a CI log shows where the time went
# (docs/benchmarks.md, "Build and test time").
export EPVIZ_TEST_STARTED=${EPVIZ_TEST_STARTED:-$(date +%s)}
stage_done() { echo "test.sh: $1 done at $(($(date +%s) - EPVIZ_TEST_STARTED)) s"; }
# The quick start's route comes first: on a fresh machine only the packages
# `scripts/setup.sh --build` installs are there at that point, so this checks
# that building the epviz binary (the README's first command, and the CI
# recipes in docs/ci.md) needs nothing more. The full build then reuses its
# objects.
EPVIZ_WERROR=ON bash scripts/build.sh --epviz-only
stage_done "quick start's set-up and the epviz binary"
EPVIZ_WERROR=ON bash scripts/build.sh
stage_done "set-up and Release build"
ctest --test-dir build --output-on-failure -j2
stage_done "Release tests"
# ASan + UBSan on the suite (build-asan/, clang, which also builds the fuzz
# targets) and TSan on the server's tests (build-tsan/); docs/architecture.md,
# "Sanitizers", has what runs where and what it costs.
sanitizers=${EPVIZ_SANITIZERS:-all}
bash tests/sanitizers/run.sh "$sanitizers"
stage_done "sanitizer passes"
# libFuzzer on the job reader, simulate's options, the page protocol, the
# sweep reader, shard manifests, golden PNGs, section files and JSON grown
# wide and deep (with a time bound per input), from the
# committed corpora, 10 s each, two at a time (a longer search is
# `scripts/fuzz.sh 600`, docs/architecture.md); in the ASan tree when the
# sanitizer pass built it, else in build-fuzz/.
fuzz_build=build-fuzz
case "$sanitizers" in all | asan) fuzz_build=build-asan ;; esac
EPVIZ_FUZZ_BUILD=$fuzz_build bash scripts/fuzz.sh 10
stage_done "fuzzing"
