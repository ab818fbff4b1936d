#!/usr/bin/env bash
# Installs what is missing, then configures and builds epviz into build/.
#
#   scripts/build.sh               everything: the binary, the test suite and
#                                  the benchmarks (scripts/test.sh)
#   scripts/build.sh --epviz-only  the epviz binary alone, with only the
#                                  packages it needs (the quick start)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  --epviz-only)
    bash scripts/setup.sh --build
    extras=OFF
    target=(--target epviz)
    ;;
  "")
    bash scripts/setup.sh --test
    extras=ON
    target=()
    ;;
  *)
    echo "scripts/build.sh: the only option is --epviz-only, not '$1'" >&2
    exit 2
    ;;
esac
# EPVIZ_WERROR=ON (set by scripts/test.sh) turns warnings in our code into errors.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DEPVIZ_WERROR="${EPVIZ_WERROR:-OFF}" \
  -DEPVIZ_BUILD_TESTS=$extras -DEPVIZ_BUILD_BENCH=$extras >/dev/null
cmake --build build "${target[@]}"
