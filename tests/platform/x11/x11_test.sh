#!/usr/bin/env bash
# The X11 window in a real X server (Xvfb), driven by xdotool:
#  1. `noneuclid run` on tests/platform/x11/static.toml (nothing moves), keys 1 (K = -1) and p (the
#     next projection: stereographic), HUD on; the window read back from the X server at exit
#     (--screenshot, XGetImage) equals, pixel for pixel, `noneuclid render` of the same scene at
#     K = -1, stereographic, with the HUD and the keys' legend;
#  2. `noneuclid run` on the kiosk scene, recording (--record): thrust held for a while, a
#     turn, K set by 3, the HUD toggled twice, then Esc; `noneuclid render --actions` of the
#     recording equals the window's last frame, pixel for pixel; and without the thrust it
#     differs (the comparison can fail);
#  3. a whole game in the window (tests/files/data/game.toml: one ship, fast asteroids): Space
#     starts it, Space held fires while the ship turns and thrusts, until the game is over (the
#     high-score table is written), then Esc; the replay of the recording equals the window.
#   x11_test.sh NONEUCLID PNG_DIFF SCENE GAME_SCENE
set -euo pipefail
noneuclid=$1 png_diff=$2 scene=$3 game=$4
for tool in Xvfb xdotool; do
    command -v "$tool" >/dev/null ||
        { echo "x11_test: $tool not found: install Debian's xvfb and xdotool (platform/debian/packages.sh's test group)" >&2; exit 1; }
done
tmp=$(mktemp -d)
xvfb_pid=
app_pid=
cleanup() {
    if [ -n "$app_pid" ]; then kill "$app_pid" 2>/dev/null || true; fi
    if [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null; then wait "$xvfb_pid" 2>/dev/null || true; fi
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

window() {  # the window's id, once it is mapped
    timeout 10 xdotool search --sync --name '^noneuclid$' | head -n 1
}
wait_app() {  # WHAT: waits for the program started in the background; a failure ends the test
    local status=0
    wait "$app_pid" || status=$?
    app_pid=
    if [ "$status" -ne 0 ]; then
        echo "x11_test: $1 exited with status $status" >&2
        exit 1
    fi
}

# 1. 600 frames at 60 fps: about 10 s for the keys to arrive, even on a loaded machine (each
#    program may take minutes there in a sanitized debug build: the time limits are generous).
timeout 240 "$noneuclid" run --display x11 --scene "$scene" --size 480x360 --frames 600 \
    --screenshot "$tmp/x11.png" &
app_pid=$!
timeout 10 xdotool key --window "$(window)" 1 p
wait_app "noneuclid run"
timeout 240 "$noneuclid" render --scene "$scene" --size 480x360 --curvature -1 --projection stereographic \
    --hud --legend keys --out "$tmp/render.png"
"$png_diff" "$tmp/x11.png" "$tmp/render.png" --exact

# 2. Until Esc; the keys as a visitor would press them.
timeout 240 "$noneuclid" run --display x11 --scene kiosk --size 400x300 --record "$tmp/run.rec" \
    --screenshot "$tmp/run.png" &
app_pid=$!
win=$(window)
timeout 10 xdotool keydown --window "$win" Up
sleep 0.6
timeout 10 xdotool keyup --window "$win" Up
timeout 10 xdotool key --window "$win" a a 3 h
sleep 0.3
timeout 10 xdotool key --window "$win" h
sleep 0.3
timeout 10 xdotool key --window "$win" Escape
wait_app "noneuclid run (recording)"
for want in "press thrust" "release thrust" "press spherical" "tap hud" "legend keys"; do
    grep -q "$want" "$tmp/run.rec" || { echo "x11_test: the recording has no '$want':" >&2; cat "$tmp/run.rec" >&2; exit 1; }
done
timeout 240 "$noneuclid" render --actions "$tmp/run.rec" --out "$tmp/replay.png"
"$png_diff" "$tmp/run.png" "$tmp/replay.png" --exact
grep -v "press thrust" "$tmp/run.rec" > "$tmp/without.rec"
timeout 240 "$noneuclid" render --actions "$tmp/without.rec" --out "$tmp/without.png"
if "$png_diff" "$tmp/run.png" "$tmp/without.png" --exact; then
    echo "x11_test: the replay without the thrust should differ from the run" >&2
    exit 1
fi

# 3. A whole game: played until the table has its score (at most 150 s: a loaded machine draws
# fewer frames a second, and the game ends only after so many of its steps), then Esc.
timeout 200 "$noneuclid" run --display x11 --scene "$game" --size 400x300 --record "$tmp/game.rec" \
    --scores "$tmp/scores" --screenshot "$tmp/game.png" &
app_pid=$!
win=$(window)
timeout 10 xdotool key --window "$win" space
sleep 0.3
timeout 10 xdotool keydown --window "$win" space
for i in $(seq 1 300); do
    [ -s "$tmp/scores" ] && break
    timeout 10 xdotool keydown --window "$win" Left
    [ $((i % 4)) = 0 ] && timeout 10 xdotool keydown --window "$win" Up
    sleep 0.25
    timeout 10 xdotool keyup --window "$win" Left Up
    sleep 0.25
done
timeout 10 xdotool keyup --window "$win" space
[ -s "$tmp/scores" ] || { echo "x11_test: the game did not end within 150 s" >&2; exit 1; }
timeout 10 xdotool key --window "$win" Escape
wait_app "noneuclid run (the game)"
for want in "press fire" "release fire" "scene $game"; do
    grep -q "$want" "$tmp/game.rec" || { echo "x11_test: the game's recording has no '$want':" >&2; cat "$tmp/game.rec" >&2; exit 1; }
done
"$noneuclid" scores --scores "$tmp/scores" 2>/dev/null | grep -q '^ 1 ' ||
    { echo "x11_test: no game in the high-score table:" >&2; cat "$tmp/scores" >&2; exit 1; }
timeout 240 "$noneuclid" render --actions "$tmp/game.rec" --out "$tmp/game-replay.png"
"$png_diff" "$tmp/game.png" "$tmp/game-replay.png" --exact
