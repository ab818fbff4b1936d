#!/usr/bin/env bash
# The README's second command (and CI's): set up, build, and run the whole test
# suite; with EPVIZ_SANITIZERS, build it again under the sanitizers (ASan + UBSan,
# and TSan for the server) and run the tests that mean something there.
set -euo pipefail
cd "$(dirname "$0")/.."
EPVIZ_WERROR=ON bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
# libFuzzer on the job reader, simulate's options and the page protocol, from
# the committed corpora, 60 s each (clang; its own build directory).
bash scripts/fuzz.sh 60
# EPVIZ_SANITIZERS=all, asan or tsan adds the sanitizer passes. They are off by
# default: the ASan build alone takes about half of CI's hour on 2 cores
# (docs/architecture.md, "Sanitizers", has the measurements).
bash tests/sanitizers/run.sh "${EPVIZ_SANITIZERS:-none}"
