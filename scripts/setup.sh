#!/usr/bin/env bash
# Installs the Debian packages epviz needs. Idempotent: packages already present
# are not reinstalled. Runs as root or via sudo.
#
#   scripts/setup.sh --runtime   what running an installed epviz needs (GL
#                                drivers, ffmpeg, the font): a user's CI that
#                                only runs `epviz check` from the .deb
#   scripts/setup.sh --build     --runtime plus what building the epviz binary
#                                needs (the README's quick start)
#   scripts/setup.sh [--test]    --build plus what the test suite, the
#                                benchmarks, the sanitizer passes, the browser
#                                tests, the Slurm test, the Python module and
#                                its tests need (the default; scripts/test.sh
#                                and CI)
set -euo pipefail

mode=test
case "${1:---test}" in
  --runtime) mode=runtime ;;
  --build) mode=build ;;
  --test) mode=test ;;
  *)
    echo "scripts/setup.sh: the option must be --runtime, --build or --test, not '$1'" >&2
    exit 2
    ;;
esac

# libegl-mesa0 is the EGL driver libegl1 dispatches to, and libgl1-mesa-dri holds
# the rasteriser it loads (swrast_dri.so); without both only OSMesa draws. The
# .deb's Depends (CMakeLists.txt, CPack) name the same packages, and
# tests/install/deb_test.py checks what a render opens against them.
runtime_packages=(
  libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 ffmpeg fonts-dejavu-core
  libturbojpeg0 libstb0 zlib1g libgsl27 libgslcblas0 libcairo2 libhdf5-103-1
)
build_packages=(
  build-essential cmake ninja-build pkg-config lld
  libeigen3-dev libboost-dev
  libcli11-dev nlohmann-json3-dev
  libosmesa6-dev libgl-dev libegl-dev libglm-dev libimgui-dev libstb-dev zlib1g-dev
  libturbojpeg0-dev libgsl-dev libcairo2-dev libhdf5-dev
)
test_packages=(
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-scipy poppler-utils librsvg2-bin strace
  chromium
  clang-format python3 clang libclang-rt-14-dev
  slurmctld slurmd slurm-client munge
  pybind11-dev python3-dev python3-numpy python3-pytest python3-h5py python3-matplotlib
)
packages=("${runtime_packages[@]}")
case "$mode" in
  build) packages+=("${build_packages[@]}") ;;
  test) packages+=("${build_packages[@]}" "${test_packages[@]}") ;;
esac

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

if [ "$mode" != test ]; then
  exit 0
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
