#!/usr/bin/env bash
# The README's first command: set up, build, and run the main job: every
# classical case integrated with its invariant drifts printed, then the gallery
# (one still per case tiled into out/gallery/gallery.png, and a short video
# per case in out/gallery/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --epviz-only
./build/epviz simulate --case all --t-end 100
./build/epviz render render_jobs/gallery.json
