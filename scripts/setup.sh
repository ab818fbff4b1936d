#!/usr/bin/env bash
# Installs every Debian package epviz needs to build, test and run.
# Idempotent: packages already present are not reinstalled. Runs as root or via sudo.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libboost-dev
  libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libosmesa6-dev libgl-dev libegl-dev libegl-mesa0 libegl1 libglm-dev libimgui-dev libstb-dev zlib1g-dev
  ffmpeg libgsl-dev python3-scipy
  libturbojpeg0-dev chromium fonts-dejavu-core
  clang-format python3 clang libclang-rt-14-dev
  slurmctld slurmd slurm-client munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
apt_updated=0
apt_install() {
  if [ "$apt_updated" -eq 0 ]; then
    "${sudo[@]}" apt-get update -qq
    apt_updated=1
  fi
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "$@"
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  echo "setup: installing ${missing[*]}"
  apt_install "${missing[@]}"
fi

# Browser tests of `epviz serve` (tests/e2e) run Node.js with playwright-core
# from the npm registry against Debian's Chromium. A machine that already has
# node and npm (from any source) keeps them. When npm fails, the e2e test
# skips and says why; everything else still builds and tests.
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "setup: installing nodejs npm"
  apt_install nodejs npm || echo "setup: warning: could not install nodejs/npm; the browser e2e test will skip" >&2
fi
e2e="$repo/tests/e2e"
if [ -d "$e2e/node_modules/playwright-core" ]; then
  echo "setup: tests/e2e node_modules present"
elif ! command -v npm >/dev/null 2>&1; then
  echo "setup: warning: no npm; the browser e2e test will skip" >&2
else
  echo "setup: npm ci in tests/e2e"
  if ! (cd "$e2e" && npm ci --no-audit --no-fund --loglevel=error >/dev/null); then
    echo "setup: warning: npm ci failed in tests/e2e; the browser e2e test will skip" >&2
  fi
fi
