#!/usr/bin/env bash
# Instructions per tessellated point and per vertex on ARM, for the fixed and double engines at
# the curvatures given, counted under qemu-user by tests/bench/insncount/arm-insncount
# (repeatable, unlike times):
#   per point   the geometry stage of the stress scene (200 bodies x 8 edges) drawn at
#               tessellation level 16 against level 8: 12,800 more points a frame;
#   per vertex  the same at level 1 (an edge is its end vertex alone), 16 vertices a body
#               against 8: 1,600 more vertices (and edges) a frame, each with its motion,
#               its projection and its edge's set-up.
# Each is the difference divided by the number of points or vertices added.
#
#   tests/bench/arm-point-insncount.sh [aarch64|armhf] [K ...]     default: aarch64 -1 -0.6 0 0.5
#   BUILD_DIR=build/p8-aarch64 to use an existing cross build directory (default build/<target>)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
target=${1:-aarch64}
shift || true
curvatures=("$@")
[ ${#curvatures[@]} -gt 0 ] || curvatures=(-1 -0.6 0 0.5)
# shellcheck source=tests/bench/arm-setup.sh
. tests/bench/arm-setup.sh
arm_setup arm-point-insncount.sh "$target" frame_probe
frames=4

count() {  # count ENGINE FRAMES K LEVEL VERTICES -> instructions
    "$counter" "$arch" "$probe" geometry "$1" stress 800x480 rgb565 "$2" 1 "$3" "$4" "$5" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
}
per_frame() {  # per_frame ENGINE K LEVEL VERTICES
    echo $(( ($(count "$1" "$frames" "$2" "$3" "$4") - $(count "$1" 0 "$2" "$3" "$4")) / frames ))
}
ratio() { awk -v d="$1" -v f="$2" 'BEGIN { printf "%.2f", d / f }'; }
echo "instructions on $target (qemu-user), stress geometry: per tessellated point (level 16 against 8),"
echo "per vertex (level 1, 16 vertices a body against 8)"
echo
echo "| K | fixed per point | double per point | double/fixed | fixed per vertex | double per vertex | double/fixed |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for K in "${curvatures[@]}"; do
    f=$(( ($(per_frame fixed "$K" 16 8) - $(per_frame fixed "$K" 8 8)) / 12800 ))
    d=$(( ($(per_frame double "$K" 16 8) - $(per_frame double "$K" 8 8)) / 12800 ))
    fv=$(( ($(per_frame fixed "$K" 1 16) - $(per_frame fixed "$K" 1 8)) / 1600 ))
    dv=$(( ($(per_frame double "$K" 1 16) - $(per_frame double "$K" 1 8)) / 1600 ))
    echo "| $K | $f | $d | $(ratio "$d" "$f") | $fv | $dv | $(ratio "$dv" "$fv") |"
done
