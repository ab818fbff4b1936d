#!/usr/bin/env bash
# Start-up cost of `epviz simulate` against a trivial C++ program linked with
# libstdc++, in CPU time per run (user + system, from the children's rusage),
# both measured in this one run so that machine load affects them alike.
#   bench/startup.sh [path/to/epviz] [runs]      (defaults: build/epviz, 50)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
epviz="${1:-$root/build/epviz}"
runs="${2:-50}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The reference: iostream and a std::string, so libstdc++ is loaded and initialised.
cat >"$work/trivial.cpp" <<'CPP'
#include <iostream>
#include <string>
int main(int argc, char**) { std::string s(argc, 'x'); std::cout << s.size() << '\n'; }
CPP
"${CXX:-c++}" -O2 -o "$work/trivial" "$work/trivial.cpp"

# CPU seconds per run of "$@", from the rusage of the children of a bash that runs it $runs times.
cpu_per_run() {
    local out
    out=$(bash -c 'for ((i = 0; i < '"$runs"'; i++)); do "$@" >/dev/null; done; times' _ "$@" | tail -1)
    # `times` prints children's user and system time as "XmY.YYYs XmY.YYYs".
    python3 - "$out" "$runs" <<'PY'
import re, sys
parts = re.findall(r"(\d+)m([\d.]+)s", sys.argv[1])
print(sum(int(m) * 60 + float(s) for m, s in parts) / int(sys.argv[2]))
PY
}

trivial=$(cpu_per_run "$work/trivial")
simulate=$(cpu_per_run "$epviz" simulate --case kovalevskaya --t-end 1 --samples 10 --csv "$work/run.csv")
python3 - "$trivial" "$simulate" "$runs" <<'PY'
import sys
trivial, simulate, runs = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
print(f"runs each:                  {runs}")
print(f"trivial C++ program:        {trivial * 1e3:7.2f} ms CPU per run")
print(f"epviz simulate (t_end 1):   {simulate * 1e3:7.2f} ms CPU per run")
print(f"ratio:                      {simulate / trivial:7.1f}x")
PY
