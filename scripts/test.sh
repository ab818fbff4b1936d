#!/usr/bin/env bash
# The README's second command (and CI's): set up, build, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
EPVIZ_WERROR=ON bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
