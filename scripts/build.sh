#!/usr/bin/env bash
# Installs what is missing, then configures and builds epviz into build/.
#
#   scripts/build.sh               the binary and the test suite, what
#                                  scripts/test.sh runs
#   scripts/build.sh --bench       the same and the benchmarks (bench/), which
#                                  no test runs
#   scripts/build.sh --epviz-only  the epviz binary alone, with only the
#                                  packages it needs (the quick start)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  --epviz-only)
    bash scripts/setup.sh --build
    tests=OFF
    bench=OFF
    target=(--target epviz)
    ;;
  "")
    bash scripts/setup.sh --test
    tests=ON
    bench=OFF
    target=()
    ;;
  --bench)
    bash scripts/setup.sh --test
    tests=ON
    bench=ON
    target=()
    ;;
  *)
    echo "scripts/build.sh: the options are --epviz-only and --bench, not '$1'" >&2
    exit 2
    ;;
esac
# EPVIZ_WERROR=ON (set by scripts/test.sh) turns warnings in our code into errors.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DEPVIZ_WERROR="${EPVIZ_WERROR:-OFF}" \
  -DEPVIZ_BUILD_TESTS=$tests -DEPVIZ_BUILD_BENCH=$bench >/dev/null
cmake --build build "${target[@]}"
