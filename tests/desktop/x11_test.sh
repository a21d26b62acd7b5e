#!/usr/bin/env bash
# The X11 window in a real X server (Xvfb): open `noneuclid run` on tests/desktop/static.toml
# (nothing moves), send it the keys 1 (K = -1), p (next projection: stereographic) and h (the
# HUD, on at start, goes off), read the window back from the X server at exit (--screenshot,
# XGetImage) and compare it with `noneuclid render` of the same scene at K = -1, stereographic,
# without HUD. Tolerance: at most 0.5% of the pixels may differ by more than 8 levels in any
# channel (png_diff); the two paths draw with the same code and options, so in practice 0.
#   x11_test.sh NONEUCLID PNG_DIFF SCENE
set -euo pipefail
noneuclid=$1 png_diff=$2 scene=$3
tmp=$(mktemp -d)
xvfb_pid=
app_pid=
cleanup() {
    [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null || true
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT INT TERM

# A free display number from 90 upward.
n=90
while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do
    n=$((n + 1))
    [ "$n" -lt 200 ] || { echo "x11_test: no free X display number from 90 to 199" >&2; exit 1; }
done
Xvfb ":$n" -screen 0 1024x768x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
xvfb_pid=$!
export DISPLAY=":$n"
# Wait (at most 10 s) until the server answers.
if ! timeout 10 bash -c "until xdpyinfo >/dev/null 2>&1 || { ! command -v xdpyinfo >/dev/null && [ -S /tmp/.X11-unix/X$n ]; }; do sleep 0.1; done"; then
    echo "x11_test: Xvfb :$n did not start within 10 s:" >&2
    cat "$tmp/xvfb.log" >&2
    exit 1
fi

# 600 frames at 60 fps: about 10 s for the keys to arrive, even on a loaded machine.
timeout 60 "$noneuclid" run --display x11 --scene "$scene" --size 480x360 --frames 600 \
    --screenshot "$tmp/x11.png" &
app_pid=$!
win=$(timeout 10 xdotool search --sync --name '^noneuclid$' | head -n 1)
timeout 10 xdotool key --window "$win" 1 p h
status=0
wait "$app_pid" || status=$?
app_pid=
if [ "$status" -ne 0 ]; then
    echo "x11_test: noneuclid run exited with status $status" >&2
    exit 1
fi

timeout 60 "$noneuclid" render --scene "$scene" --size 480x360 --curvature -1 --projection stereographic \
    --out "$tmp/render.png"
"$png_diff" "$tmp/x11.png" "$tmp/render.png"
