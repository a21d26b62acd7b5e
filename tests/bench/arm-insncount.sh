#!/usr/bin/env bash
# Instructions per call on ARM for each fixed-point function against std:: double and float,
# counted under qemu-user by tests/bench/insncount/arm-insncount (repeatable, unlike times).
#
#   tests/bench/arm-insncount.sh            # aarch64 (Cortex-A53 tuning), docs/performance.md's table
#   tests/bench/arm-insncount.sh armhf      # 32-bit ARMv7 build
#
# Needs crossbuild-essential-arm64 / -armhf, qemu-user and a C compiler for the counter's
# plugin (installed here through platform/debian/deps.sh if missing: tests/bench/arm-setup.sh).
# ARM_INSNCOUNT=PATH uses another counter with the same interface; BUILD_DIR=build/p8-aarch64
# an existing cross build directory (default build/<target>).
# Per call = (count with N calls - count with 0 calls) / N, minus the loop's own cost
# (insn_probe nop: load an input, accumulate, count), which is printed too.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
target=${1:-aarch64}
# shellcheck source=tests/bench/arm-setup.sh
. tests/bench/arm-setup.sh
arm_setup arm-insncount.sh "$target" insn_probe
n=20000

count() {  # count FUNCTION IMPL CALLS -> instructions
    "$counter" "$arch" "$probe" "$1" "$2" "$3" 2>&1 >/dev/null | awk '/^insns:/ {print $2}'
}
per_call() {  # per_call FUNCTION IMPL -> instructions per call, loop included (x100, integer)
    local base full
    base=$(count "$1" "$2" 0)
    full=$(count "$1" "$2" "$n")
    echo $(( (full - base) * 100 / n ))
}
loop=$(per_call nop fixed)
fmt() { printf '%d.%02d' $(( $1 / 100 )) $(( $1 % 100 )); }
echo "instructions per call on $target (qemu-user, N=$n calls, loop of $(fmt "$loop") subtracted)"
echo
echo "| function | fixed | double | float | double/fixed | float/fixed |"
echo "|---|---:|---:|---:|---:|---:|"
for f in sin cos atan2 asin acos sqrt exp log sinh cosh asinh acosh Sf Cf ASf; do
    fx=$(( $(per_call "$f" fixed) - loop ))
    db=$(( $(per_call "$f" double) - loop ))
    fl=$(( $(per_call "$f" float) - loop ))
    echo "| $f | $(fmt "$fx") | $(fmt "$db") | $(fmt "$fl") | $(fmt $(( db * 100 / fx ))) | $(fmt $(( fl * 100 / fx ))) |"
done
