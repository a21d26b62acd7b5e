#!/usr/bin/env bash
# Instructions per tessellated point on ARM: the geometry stage of the stress scene drawn at
# tessellation level 8 and at level 16 (200 bodies x 8 edges: 12,800 more points a frame),
# the difference divided by 12,800, for the fixed and double engines at the curvatures given.
# Counted under qemu-user by ../shared/tools/arm-insncount (repeatable, unlike times).
#
#   tests/bench/arm-point-insncount.sh [aarch64|armhf] [K ...]     default: aarch64 -1 -0.6 0 0.5
#   BUILD_DIR=build/p8-aarch64 to use an existing cross build directory (default build/<target>)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
target=${1:-aarch64}
shift || true
curvatures=("$@")
[ ${#curvatures[@]} -gt 0 ] || curvatures=(-1 -0.6 0 0.5)
tool=arm-point-insncount.sh
. tests/bench/frame-probe-setup.sh
frames=4

count() {  # count ENGINE FRAMES K LEVEL -> instructions
    "$counter" "$arch" "$probe" geometry "$1" stress 800x480 rgb565 "$2" 1 "$3" "$4" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
}
per_frame() {  # per_frame ENGINE K LEVEL
    echo $(( ($(count "$1" "$frames" "$2" "$3") - $(count "$1" 0 "$2" "$3")) / frames ))
}
echo "instructions per tessellated point on $target: stress geometry, level 16 against level 8 (qemu-user)"
echo
echo "| K | fixed | double | double/fixed |"
echo "|---|---:|---:|---:|"
for K in "${curvatures[@]}"; do
    f=$(( ($(per_frame fixed "$K" 16) - $(per_frame fixed "$K" 8)) / 12800 ))
    d=$(( ($(per_frame double "$K" 16) - $(per_frame double "$K" 8)) / 12800 ))
    echo "| $K | $f | $d | $(awk -v d="$d" -v f="$f" 'BEGIN { printf "%.2f", d / f }') |"
done
