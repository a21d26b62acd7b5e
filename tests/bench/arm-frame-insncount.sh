#!/usr/bin/env bash
# Instructions per kiosk frame on ARM, counted under qemu-user by
# tests/bench/insncount/arm-insncount (repeatable, unlike times): the whole frame and each stage, fixed, double and float engines.
#
#   tests/bench/arm-frame-insncount.sh [aarch64|armhf] [SCENE] [WxH] [FORMAT]
#   defaults: aarch64 kiosk 800x480 rgb565 (the Pi's display)
#   SCENE game:A:B is the game in play with A asteroids and B bullets in flight; its table adds
#   the stage collide, the game's collision tests alone. SCENE textured (five textured bodies and
#   a filled one) or filled (the same with colours for textures) adds fill, the fills alone, and
#   fillmemset, a memset of as many pixels as they cover
#   BUILD_DIR=build/p8-aarch64 to use an existing cross build directory (default build/<target>)
#   K=-0.6 to set the curvature (the kiosk starts at K = 0), K=sweep to change it every frame as
#   attract mode does (the frame stage then rebuilds every body's shape cache); FRAMES=N (default 10)
#
# Per frame = (count with N frames - count with 0 frames) / N; both runs build the world and
# draw one warm-up frame (tests/bench/frame_probe.cpp). frame = world step + draw_world +
# copy_canvas to a second buffer (the kiosk's per-frame work, HUD aside).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
target=${1:-aarch64}
scene=${2:-kiosk}
size=${3:-800x480}
format=${4:-rgb565}
# shellcheck source=tests/bench/arm-setup.sh
. tests/bench/arm-setup.sh
arm_setup arm-frame-insncount.sh "$target" frame_probe
n=${FRAMES:-10}

count() {  # count STAGE ENGINE FRAMES -> instructions
    if [ -n "${K:-}" ]; then
        "$counter" "$arch" "$probe" "$1" "$2" "$scene" "$size" "$format" "$3" 1 "$K" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
    else
        "$counter" "$arch" "$probe" "$1" "$2" "$scene" "$size" "$format" "$3" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
    fi
}
per_frame() {
    local base full
    base=$(count "$1" "$2" 0)
    full=$(count "$1" "$2" "$n")
    echo $(( (full - base) / n ))
}
echo "instructions per frame on $target: $scene at $size $format${K:+, K = $K} (qemu-user, N=$n frames)"
echo
echo "| stage | fixed | double | float | double/fixed |"
echo "|---|---:|---:|---:|---:|"
stages="frame step backdrop geometry raster copy memcpy"
case $scene in
    game:*) stages="$stages collide" ;;
    textured | filled) stages="$stages fill fillmemset" ;;
esac
for stage in $stages; do
    f=$(per_frame "$stage" fixed)
    d=$(per_frame "$stage" double)
    fl=$(per_frame "$stage" float)
    ratio=$(awk -v d="$d" -v f="$f" 'BEGIN { if (f > 0) printf "%.2f", d / f; else print "-" }')
    echo "| $stage | $f | $d | $fl | $ratio |"
done
