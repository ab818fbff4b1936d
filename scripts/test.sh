#!/usr/bin/env bash
# The README's second command (and CI's): set up, build, and run the whole test
# suite; then build it again under the sanitizers (ASan + UBSan, and TSan for the
# server) and run the tests that mean something there (tests/sanitizers/run.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
EPVIZ_WERROR=ON bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
# EPVIZ_SANITIZERS=asan, tsan or none runs fewer of them (CI runs all).
bash tests/sanitizers/run.sh "${EPVIZ_SANITIZERS:-all}"
