#!/usr/bin/env bash
# Regenerates the golden images: the demo's pictures (src/app/figures.cpp, the one table of the
# figures) drawn by the double engine (the reference) at 480x480 without the HUD, which
# tests/render/test_golden.cpp compares the engines with. Run it only when a change to the
# drawing is intended, look at the pictures, and commit them with that change.
#   tests/render/golden/regenerate.sh [path/to/noneuclid]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
bin=${1:-../../../build/release/noneuclid}
"$bin" demo --engine double --size 480x480 --no-hud --out-dir .
