#!/usr/bin/env bash
# Runs a route of the docs on a fresh Debian 12 root made by debootstrap, so
# that it sees only the packages it installs itself, and times it. For the
# measurements in docs/benchmarks.md; not part of the test command (it
# downloads a Debian base system and builds epviz from nothing).
#
#   scripts/fresh_root.sh quickstart DIR   DIR gets a Debian 12 root with what
#       this project's development machines start with (compiler, CMake, Ninja,
#       git, Python, GoogleTest, Google Benchmark, clang-format); a clean clone
#       of the committed HEAD runs the README's first command in it.
#   scripts/fresh_root.sh ci-recipe DIR    DIR gets a bare Debian 12 root (what
#       the recipes' `debian:12` image has, and git to clone); the GitLab
#       recipe's script lines from docs/ci.md run in a clean clone there.
#
# Needs root (debootstrap, chroot, mounts) and access to Debian's archive.
# Prints one line per stage with the seconds since the start; the log of the
# route is DIR/route.log.
set -euo pipefail
mode="${1:-}"
dir="${2:-}"
case "$mode" in
  quickstart | ci-recipe) ;;
  *)
    echo "scripts/fresh_root.sh: the first argument must be quickstart or ci-recipe, not '$mode'" >&2
    exit 2
    ;;
esac
if [ -z "$dir" ] || [ -e "$dir" ]; then
  echo "scripts/fresh_root.sh: the second argument must name a directory that does not exist yet" >&2
  exit 2
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "scripts/fresh_root.sh: must run as root (debootstrap and chroot)" >&2
  exit 2
fi
repo="$(cd "$(dirname "$0")/.." && pwd)"
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >/dev/null

start=$(date +%s)
stage() { echo "fresh_root: $1 at $(($(date +%s) - start)) s"; }

root="$(realpath -m "$dir")/root"
mkdir -p "$root"
cleanup() {
  for m in proc sys dev; do umount -R "$root/$m" 2>/dev/null || true; done
}
trap cleanup EXIT
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$dir/debootstrap.log"
mount -t proc proc "$root/proc"
mount --rbind /sys "$root/sys"
mount --rbind /dev "$root/dev"
cp /etc/resolv.conf "$root/etc/resolv.conf"
in_root() { chroot "$root" env HOME=/root DEBIAN_FRONTEND=noninteractive bash -c "$1"; }
if [ "$mode" = quickstart ]; then
  in_root "apt-get update -qq && apt-get install -y -qq --no-install-recommends git ca-certificates \
    g++ make cmake ninja-build python3 libgtest-dev libgmock-dev libbenchmark-dev clang-format >/dev/null && apt-get clean"
fi
git clone -q "$repo" "$root/root/epviz"
stage "root ready ($(git -C "$repo" rev-parse --short HEAD))"

route_start=$(date +%s)
if [ "$mode" = quickstart ]; then
  # The README's first command, exactly as it is written there.
  command=$(sed -n 's/^    \(bash scripts\/quickstart.sh\).*/\1/p' "$repo/README.md" | head -n 1)
else
  # The GitLab recipe's script lines, as docs/ci.md shows them.
  command=$(awk '/^render-check:/{f=1} f&&/^  script:/{s=1;next} s&&/^    - /{sub(/^    - /,"");print;next} s{exit}' \
    "$repo/docs/ci.md" | paste -sd'&' | sed 's/&/ \&\& /g')
fi
if [ -z "$command" ]; then
  echo "scripts/fresh_root.sh: found no command to run in the docs" >&2
  exit 1
fi
echo "fresh_root: running: $command"
rc=0
in_root "cd /root/epviz && $command" >"$dir/route.log" 2>&1 || rc=$?
echo "fresh_root: the route took $(($(date +%s) - route_start)) s and exited $rc (log: $dir/route.log)"
stage "done"
exit $rc
