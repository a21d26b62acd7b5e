#!/usr/bin/env bash
# Regenerates the golden images from the double engine (the reference engine): run it only when
# a change to the drawing is intended, look at the pictures, and commit them with that change.
#   tests/golden/regenerate.sh [path/to/noneuclid]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
bin=${1:-../../build/release/noneuclid}
# name, then the render options (kept in step with tests/render/test_golden.cpp)
while read -r name opts; do
    [ -z "$name" ] && continue
    # shellcheck disable=SC2086
    "$bin" render --engine double --size 480x480 $opts --out "$name.png"
done <<'LIST'
fig1 --scene fig1 --frames 120
fig14 --scene fig14 --frames 600 --timelapse 40
fig15 --scene fig15 --frames 600 --timelapse 40
fig16 --scene fig16 --frames 120 --timelapse 15
fig17 --scene fig17 --frames 250 --timelapse 25
kiosk --scene kiosk --frames 60 --aa
LIST
