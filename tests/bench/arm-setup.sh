# Sourced by arm-frame-insncount.sh and arm-point-insncount.sh (from the repository's root, with
# $target and $tool set): installs what is missing (platform/debian/deps.sh), sets arch and
# counter for tests/bench/insncount/arm-insncount (ARM_INSNCOUNT=PATH for another counter with
# the same interface), builds frame_probe in BUILD_DIR (default build/<target>, configured with
# the cross preset if it is not yet) and sets probe to it; or says why not and exits 2.
case $target in
    aarch64) arch=aarch64; pkg=crossbuild-essential-arm64 ;;
    armhf) arch=arm; pkg=crossbuild-essential-armhf ;;
    *) echo "$tool: target must be aarch64 or armhf, not '$target'." >&2; exit 2 ;;
esac
counter=${ARM_INSNCOUNT:-tests/bench/insncount/arm-insncount}
if [ ! -x "$counter" ]; then
    echo "$tool: the counter $counter is missing or not executable (ARM_INSNCOUNT names another)." >&2
    exit 2
fi
. platform/debian/deps.sh
noneuclid_deps g++ cmake make "$pkg" qemu-user gcc libgtest-dev libglm-dev libtomlplusplus-dev
build=${BUILD_DIR:-build/$target}
if [ ! -f "$build/CMakeCache.txt" ]; then cmake --preset "$target" -B "$build" >/dev/null; fi
cmake --build "$build" --target frame_probe -j 2 >/dev/null
probe=$build/frame_probe
