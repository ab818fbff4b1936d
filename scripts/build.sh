#!/usr/bin/env bash
# Installs what is missing, then configures and builds epviz into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# EPVIZ_WERROR=ON (set by scripts/test.sh) turns warnings in our code into errors.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DEPVIZ_WERROR="${EPVIZ_WERROR:-OFF}" >/dev/null
cmake --build build
