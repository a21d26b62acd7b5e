# Sourced by arm-frame-insncount.sh and arm-point-insncount.sh (from the repository's root, with
# $target and $tool set): sets arch and counter for ../shared/tools/arm-insncount, builds
# frame_probe in BUILD_DIR (default build/<target>, configured with the cross preset if it is
# not yet) and sets probe to it; or says why not and exits 2.
case $target in
    aarch64) arch=aarch64 ;;
    armhf) arch=arm ;;
    *) echo "$tool: target must be aarch64 or armhf, not '$target'." >&2; exit 2 ;;
esac
counter=${ARM_INSNCOUNT:-../shared/tools/arm-insncount/arm-insncount}
if [ ! -x "$counter" ]; then
    echo "$tool: $counter not found: check out ../shared beside this repository or set ARM_INSNCOUNT." >&2
    exit 2
fi
build=${BUILD_DIR:-build/$target}
if [ ! -f "$build/CMakeCache.txt" ]; then cmake --preset "$target" -B "$build" >/dev/null; fi
cmake --build "$build" --target frame_probe -j 2 >/dev/null
probe=$build/frame_probe
