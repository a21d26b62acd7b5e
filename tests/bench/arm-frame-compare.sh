#!/usr/bin/env bash
# Instructions per kiosk frame on ARM, this tree's frame_probe beside another's (an earlier
# commit's), counted in one run under qemu-user by tests/bench/insncount/arm-insncount: the
# before/after figures of docs/performance.md.
#
#   BEFORE=/path/to/other/build/aarch64/frame_probe tests/bench/arm-frame-compare.sh [aarch64|armhf] [SCENE] [WxH] [FORMAT]
#   defaults: aarch64 kiosk 800x480 rgb565; FRAMES=N (default 5); BUILD_DIR as arm-frame-insncount.sh
#
# Build the other probe in a checkout of the other commit with the same preset:
#   git worktree add /tmp/before <commit> && cd /tmp/before && cmake --preset aarch64 &&
#   cmake --build build/aarch64 --target frame_probe -j 2
# Rows: K = 0 (the kiosk's start), -0.6, +1, and K sweeping every frame (attract mode) from
# -0.6 and (this tree only: the older probe may not know it) from +0.95, through the antipode.
# Per frame = (count with N frames - count with 0) / N, as arm-frame-insncount.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
target=${1:-aarch64}
scene=${2:-kiosk}
size=${3:-800x480}
format=${4:-rgb565}
if [ -z "${BEFORE:-}" ] || [ ! -x "$BEFORE" ]; then
    echo "arm-frame-compare.sh: set BEFORE to another build's frame_probe (an executable file), e.g. BEFORE=/tmp/before/build/aarch64/frame_probe." >&2
    exit 2
fi
# shellcheck source=tests/bench/arm-setup.sh
. tests/bench/arm-setup.sh
arm_setup arm-frame-compare.sh "$target" frame_probe
n=${FRAMES:-5}

count() {  # count PROBE ENGINE K FRAMES -> instructions
    "$counter" "$arch" "$1" frame "$2" "$scene" "$size" "$format" "$4" 1 "$3" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
}
per_frame() {  # per_frame PROBE ENGINE K
    local base full
    base=$(count "$1" "$2" "$3" 0)
    full=$(count "$1" "$2" "$3" "$n")
    echo $(( (full - base) / n ))
}
echo "instructions per frame on $target: $scene at $size $format (qemu-user, N=$n frames)"
echo "before: $BEFORE"
echo "after:  $probe"
echo
echo "| K | fixed before | fixed after | after/before | double before | double after | after/before |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for k in 0 -0.6 1 sweep sweep@0.95; do
    row="| $k"
    for engine in fixed double; do
        if [ "$k" = sweep@0.95 ]; then b=-; else b=$(per_frame "$BEFORE" "$engine" "$k"); fi
        a=$(per_frame "$probe" "$engine" "$k")
        ratio=$(awk -v a="$a" -v b="$b" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "-" }')
        row="$row | $b | $a | $ratio"
    done
    echo "$row |"
done
