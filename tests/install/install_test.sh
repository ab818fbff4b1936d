#!/usr/bin/env bash
# The installed tree works on its own: `cmake --install` into a temporary
# prefix, moved elsewhere, with the source tree hidden (EPVIZ_IGNORE_SOURCE_TREE),
# renders a job through EGL and through OSMesa (the same pixels), serves its page,
# and `simulate` neither needs nor loads any GL library.
#   install_test.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d)"
server=""
cleanup() {
    [[ -n "$server" ]] && kill "$server" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/prefix" >/dev/null
mv "$work/prefix" "$work/moved"  # relocated: nothing may point at the first prefix
epviz="$work/moved/bin/epviz"
data="$work/moved/share/epviz"
for f in shaders assets/serve.html render_jobs/kovalevskaya.json; do
    [[ -e "$data/$f" ]] || fail "not installed: share/epviz/$f"
done
[[ -f "$work/moved/share/doc/epviz/README.md" ]] || fail "README not installed"
export EPVIZ_IGNORE_SOURCE_TREE=1
unset EPVIZ_DATA_DIR EPVIZ_SHADER_DIR
cd "$work"

"$epviz" --version | tee "$work/version.txt"
grep -Eq '^epviz [0-9]+\.[0-9]+\.[0-9]+ \(git ([0-9a-f]+|unknown)\)' "$work/version.txt" || fail "--version: no version line"
grep -q '^GL backend (auto): egl' "$work/version.txt" || fail "--version: auto should choose EGL here"

# The same frame through both backends, from the installed job and shaders.
for gl in egl osmesa; do
    EPVIZ_GL=$gl "$epviz" render "$data/render_jobs/kovalevskaya.json" --frames 0 --width 160 --height 120 \
        --format png --out "$work/$gl" --quiet --report-json "$work/$gl.json"
    grep -q "\"gl_backend\": \"$gl\"" "$work/$gl.json" || fail "$gl: report does not name the backend"
done
cmp "$work/egl/kovalevskaya_0000.png" "$work/osmesa/kovalevskaya_0000.png" ||
    fail "EGL and OSMesa frames differ (both are llvmpipe: they should not)"

# An unknown backend is bad input: one line, exit 2.
set +e
EPVIZ_GL=glx "$epviz" render "$data/render_jobs/kovalevskaya.json" --frames 0 --out "$work/x" --quiet 2>"$work/err.txt"
rc=$?
set -e
[[ $rc -eq 2 && $(wc -l <"$work/err.txt") -eq 1 ]] || fail "EPVIZ_GL=glx: want one line and exit 2, got $rc: $(cat "$work/err.txt")"

# GL libraries shadowed by garbage files of the same sonames: simulate never
# opens them; a render names the package to install.
mkdir "$work/shadow"
for lib in libOSMesa.so.8 libEGL.so.1 libGL.so.1 libLLVM-15.so.1; do echo garbage >"$work/shadow/$lib"; done
LD_LIBRARY_PATH="$work/shadow" LD_DEBUG=libs "$epviz" simulate --case kovalevskaya --t-end 1 --samples 10 \
    --csv "$work/run.csv" 2>"$work/libs.txt" >/dev/null || fail "simulate failed with GL libraries shadowed"
if grep -Eq 'libOSMesa|libEGL|libGL|libLLVM' "$work/libs.txt"; then fail "simulate looked for a GL library"; fi
set +e
LD_LIBRARY_PATH="$work/shadow" EPVIZ_GL=osmesa "$epviz" render "$data/render_jobs/kovalevskaya.json" --frames 0 \
    --out "$work/y" --quiet 2>"$work/err.txt"
rc=$?
set -e
[[ $rc -eq 1 ]] || fail "render with a broken libOSMesa: want exit 1, got $rc"
grep -q 'libosmesa6' "$work/err.txt" || fail "the error does not name the package: $(cat "$work/err.txt")"

# `auto` takes EGL when libOSMesa is broken, and falls back to OSMesa when libEGL is.
for pair in libOSMesa.so.8:egl libEGL.so.1:osmesa; do
    lib=${pair%%:*} want=${pair##*:}
    rm -rf "$work/only" && mkdir "$work/only" && echo garbage >"$work/only/$lib"
    LD_LIBRARY_PATH="$work/only" EPVIZ_GL=auto "$epviz" render "$data/render_jobs/kovalevskaya.json" --frames 0 \
        --width 64 --height 48 --format png --out "$work/auto" --quiet --report-json "$work/auto.json" ||
        fail "auto with a broken $lib did not render"
    grep -q "\"gl_backend\": \"$want\"" "$work/auto.json" || fail "auto with a broken $lib: want $want"
done

# The installed page is served.
"$epviz" serve --port 0 >"$work/serve.txt" 2>"$work/serve_err.txt" &
server=$!
for _ in $(seq 100); do
    grep -q 'http://' "$work/serve.txt" && break
    sleep 0.1
done
url=$(grep -o 'http://[^ ]*' "$work/serve.txt") || fail "serve printed no address: $(cat "$work/serve_err.txt")"
python3 -c 'import sys, urllib.request; sys.stdout.write(urllib.request.urlopen(sys.argv[1], timeout=10).read().decode())' \
    "$url" >"$work/page.html"
grep -qi '<html' "$work/page.html" || fail "GET $url did not return the page"
kill "$server"
wait "$server" || true
server=""
echo "installed tree OK"
