# shellcheck shell=bash
# The set-up the ARM bench scripts share (arm-insncount.sh, arm-frame-insncount.sh,
# arm-frame-compare.sh, arm-point-insncount.sh), sourced from the repository's root:
#
#   arm_setup TOOL TARGET PROBE
#
# TOOL is the script's name (for its messages), TARGET aarch64 or armhf, PROBE the program to
# count (insn_probe, frame_probe). Installs what is missing (the cross-<arch> group of
# platform/debian/packages.sh, through platform/debian/deps.sh), sets arch and counter for
# tests/bench/insncount/arm-insncount (ARM_INSNCOUNT=PATH for another counter with the same
# interface), builds PROBE in BUILD_DIR (default build/<TARGET>, configured with the TARGET
# preset if it is not yet) and sets probe to it; or says why not and exits 2.

# shellcheck disable=SC2034  # arch, counter and probe are results, for the scripts sourcing this
arm_setup() {
    local tool=$1 target=$2 target_probe=$3 group build
    case $target in
        aarch64) arch=aarch64; group=cross-arm64 ;;
        armhf) arch=arm; group=cross-armhf ;;
        *) echo "$tool: target must be aarch64 or armhf, not '$target'." >&2; exit 2 ;;
    esac
    counter=${ARM_INSNCOUNT:-tests/bench/insncount/arm-insncount}
    if [ ! -x "$counter" ]; then
        echo "$tool: the counter $counter is missing or not executable (ARM_INSNCOUNT names another)." >&2
        exit 2
    fi
    # shellcheck source=platform/debian/deps.sh
    . platform/debian/deps.sh
    # shellcheck source=platform/debian/packages.sh
    . platform/debian/packages.sh
    noneuclid_install "$group"    # g++ brings gcc, the counter's plugin's compiler
    build=${BUILD_DIR:-build/$target}
    if [ ! -f "$build/CMakeCache.txt" ]; then cmake --preset "$target" -B "$build" >/dev/null; fi
    cmake --build "$build" --target "$target_probe" -j "$(nproc)" >/dev/null
    probe=$build/$target_probe
}
