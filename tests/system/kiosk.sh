# shellcheck shell=dash
# (busybox sh, an ash, runs it; shellcheck 0.9 checks ash as dash.)
# Guest script of the system test (tests/system/run), busy-box sh in the VM, helpers from
# guest-lib.sh. /t/params.sh (written by the host) sets BINARIES: the static noneuclid builds
# in /t to try, e.g. "noneuclid-gpiod1 noneuclid-gpiod2" (libgpiod v1 and v2 backends).
#
# For each binary:
#   buttons   `noneuclid buttons --input gpio` sees a press and a release of thrust (wiring);
#   kiosk on the bochs framebuffer (XRGB8888), cirrus (DRM fbdev emulation at 16 bpp: RGB565,
#             red at bit 11, the Pi 0-3 layout) and vfb (16 bpp, red at bit 0): run with
#             stdin on tty1 (so it takes the VT: KD_GRAPHICS while it runs, KD_TEXT after),
#             hold thrust, press and release curvature_down, release thrust, press quit; the
#             recording (/out/<case>.rec), the frame count (--stats) and the framebuffer
#             (/out/<case>.raw + .info) go to the host, which renders and compares;
#   busy      a second noneuclid asking for the lines the first one holds fails with the
#             busy-line sentence; the first one, stopped by SIGTERM, restores the VT.
# Once, on bochs: the game: fire starts a game, then held fires shots; quit while the bullets
# are in flight; the recording and the framebuffer go to the host, which renders and compares,
# and counts the bullets' colour on the framebuffer.
# Once: `--frames 30` with no input stops after exactly 30 frames (stdin not a VT), the same
# on vfb reloaded at 24 bpp, and a missing framebuffer (/dev/fb7) fails with its sentence.
#
# fbcon is kept off every framebuffer (the kernel command line maps the consoles to fb7, which
# does not exist: the VTs run on the dummy console), so that restoring KD_TEXT at exit does not
# repaint the console over the picture before it is read back; the VT's KD mode is still real
# and is checked while noneuclid runs and after it exits.

# Written by the host for this run (tests/system/run, input-test).
# shellcheck source=/dev/null
. /t/params.sh
TTY=/dev/tty1
THRUST=0 CURVATURE_DOWN=4 QUIT=7 FIRE=8
EXPECTED_SEQUENCE="press thrust
press curvature_down
release curvature_down
release thrust"

bochs=$(fb_by_name bochs-drmdrmfb) || bochs=""
cirrus=$(fb_by_name cirrusdrmfb) || cirrus=""
vfb=$(fb_by_name "Virtual FB") || vfb=""
check "bochs framebuffer present" [ -n "$bochs" ]
check "cirrus framebuffer present (RGB565, red at bit 11, as on a Pi 0-3)" [ -n "$cirrus" ]
check "vfb framebuffer present" [ -n "$vfb" ]
check "gpio-sim chip noneuclid-sim live" sim_chip noneuclid-sim 9
check "fbcon is off the framebuffers (fbcon=map:7)" [ "$(cat /sys/class/vtconsole/vtcon1/name 2>/dev/null)" = "(M) dummy device" ]

# quit_run NAME: presses and releases quit, waits for the run in $_pid and checks it ended well
# (its log, $_out.log, shown).
quit_run() {
    sim_pull "$QUIT" pull-down
    sleep 0.1
    sim_pull "$QUIT" pull-up
    wait "$_pid"
    _rc=$?
    cat "$_out.log"
    check "$1: exit 0" [ "$_rc" = 0 ]
}

# The last line of a log: the error sentence.
last_line() { tail -n 1 "$1"; }

# is_sentence LINE PART...: "noneuclid: ..." ending in a full stop, containing every PART.
# shellcheck disable=SC2317  # called only through check, which shellcheck does not follow
is_sentence() {
    _l=$1
    shift
    case $_l in
        "noneuclid: "*.) contains "$_l" "$@" ;;
        *) return 1 ;;
    esac
}

buttons_case() {  # BINARY
    _out=/out/$1-buttons
    "$1" buttons --board /t/board.toml --input gpio --events 2 --timeout 20 > "$_out.txt" 2> "$_out.log" &
    _pid=$!
    wait_for "$_out.log" "gpio: " "$_pid"
    sleep 0.2
    sim_pull "$THRUST" pull-down
    sleep 0.2
    sim_pull "$THRUST" pull-up
    wait "$_pid"
    _rc=$?
    cat "$_out.log"
    check "$1 buttons: exit 0" [ "$_rc" = 0 ]
    check "$1 buttons: press and release of thrust" [ "$(cat "$_out.txt")" = "press thrust
release thrust" ]
}

kiosk_case() {  # NAME BINARY FRAMEBUFFER
    _out=/out/$1
    "$2" run --display "fbdev:$3" --input gpio --board /t/board.toml --scene kiosk --frames 100000 \
        --no-hud --record "$_out.rec" --stats < "$TTY" > "$_out.log" 2>&1 &
    _pid=$!
    if wait_for "$_out.log" "console in graphics mode" "$_pid"; then
        check "$1: VT in graphics mode while running" [ "$(probe kdmode "$TTY")" = graphics ]
    else
        check "$1: started on the VT" false
    fi
    sleep 0.3
    sim_pull "$THRUST" pull-down
    sleep 0.4
    sim_pull "$CURVATURE_DOWN" pull-down
    sleep 0.3
    sim_pull "$CURVATURE_DOWN" pull-up
    sleep 0.3
    sim_pull "$THRUST" pull-up
    sleep 0.3
    quit_run "$1"
    check "$1: VT back in text mode" [ "$(probe kdmode "$TTY")" = text ]
    echo "recorded:"
    cat "$_out.rec"
    check "$1: recorded exactly hold thrust, curvature_down, release" \
        [ "$(grep -E '^[0-9]' "$_out.rec" | cut -d' ' -f2-)" = "$EXPECTED_SEQUENCE" ]
    sed -n 's/^noneuclid: \([0-9]*\) frames in .*/\1/p' "$_out.log" > "$_out.frames"
    check "$1: frame count reported" [ -s "$_out.frames" ]
    check "$1: the recording ends with that frame count" [ "$(sed -n 's/^frames //p' "$_out.rec")" = "$(cat "$_out.frames")" ]
    fb_dump "$3" "$_out"
    check "$1: framebuffer read back" [ -s "$_out.raw" ]
}

game_case() {  # BINARY FRAMEBUFFER
    _out=/out/game
    "$1" run --display "fbdev:$2" --input gpio --board /t/board.toml --scene asteroids --no-aa --frames 100000 \
        --scores /out/game-scores --record "$_out.rec" --stats < "$TTY" > "$_out.log" 2>&1 &
    _pid=$!
    wait_for "$_out.log" "console in graphics mode" "$_pid" || check "game: started on the VT" false
    sleep 0.3
    sim_pull "$FIRE" pull-down    # the "press fire" screen: a game begins
    sleep 0.2
    sim_pull "$FIRE" pull-up
    sleep 0.8
    sim_pull "$FIRE" pull-down    # held: a shot every 0.2 s
    sleep 0.7
    quit_run game
    cat "$_out.rec"
    check "game: fire pressed twice, released once" \
        [ "$(grep -E '^[0-9]' "$_out.rec" | cut -d' ' -f2- | tr '\n' ,)" = "press fire,release fire,press fire," ]
    sed -n 's/^noneuclid: \([0-9]*\) frames in .*/\1/p' "$_out.log" > "$_out.frames"
    check "game: the recording ends with the frame count" [ "$(sed -n 's/^frames //p' "$_out.rec")" = "$(cat "$_out.frames")" ]
    fb_dump "$2" "$_out"
}

busy_case() {  # BINARY
    _out=/out/$1-busy
    "$1" run --display "fbdev:$vfb" --input gpio --board /t/board.toml --frames 100000 --no-hud \
        < "$TTY" > "$_out.holder.log" 2>&1 &
    _pid=$!
    wait_for "$_out.holder.log" "console in graphics mode" "$_pid"
    "$1" run --display "fbdev:$bochs" --input gpio --board /t/board.toml --frames 10 --no-hud \
        < /dev/null > "$_out.log" 2>&1
    _rc=$?
    cat "$_out.log"
    check "$1 busy line: exit status not 0" [ "$_rc" != 0 ]
    check "$1 busy line: one sentence naming the line, the chip and its user" \
        is_sentence "$(last_line "$_out.log")" "line 0" "noneuclid-sim" "in use"
    kill -TERM "$_pid"
    wait "$_pid"
    cat "$_out.holder.log"
    check "$1 busy line: the holder stops on SIGTERM" contains "$(cat "$_out.holder.log")" "stopped by signal 15"
    check "$1 busy line: the holder restored the VT" [ "$(probe kdmode "$TTY")" = text ]
}

first=""
for bin in $BINARIES; do
    echo "== $bin"
    buttons_case "$bin"
    [ -n "$bochs" ] && kiosk_case "$bin-bochs" "$bin" "$bochs"
    [ -n "$cirrus" ] && kiosk_case "$bin-cirrus" "$bin" "$cirrus"
    [ -n "$vfb" ] && kiosk_case "$bin-vfb" "$bin" "$vfb"
    [ -n "$vfb" ] && [ -n "$bochs" ] && busy_case "$bin"
    [ -z "$first" ] && first=$bin
done

echo "== $first: the game on bochs"
[ -n "$bochs" ] && game_case "$first" "$bochs"

echo "== $first: --frames 30, no input, stdin not a VT"
"$first" run --display "fbdev:$bochs" --input none --board /t/board.toml --scene kiosk --frames 30 --no-hud \
    --stats < /dev/null > /out/frames30.log 2>&1
rc=$?
cat /out/frames30.log
check "--frames 30: exit 0" [ "$rc" = 0 ]
check "--frames 30: 30 frames" contains "$(cat /out/frames30.log)" "noneuclid: 30 frames in "
fb_dump "$bochs" /out/frames30

echo "== $first: 24 bpp: vfb reloaded at 800x480-24 (red at bit 0), --frames 30"
if [ -n "$vfb" ] && rmmod vfb && insmod /lib/modules/vfb.ko vfb_enable=1 videomemorysize=2097152 \
        mode_option=800x480M-24@60; then
    vfb24=$(fb_by_name "Virtual FB") || vfb24=""
    check "vfb at 24 bpp present" [ -n "$vfb24" ]
    check "vfb at 24 bpp is 24 bpp" contains "$(probe fb "$vfb24")" " bpp=24 "
    "$first" run --display "fbdev:$vfb24" --input none --board /t/board.toml --scene kiosk --frames 30 \
        --no-hud --stats < /dev/null > /out/vfb24.log 2>&1
    rc=$?
    cat /out/vfb24.log
    check "24 bpp --frames 30: exit 0" [ "$rc" = 0 ]
    fb_dump "$vfb24" /out/vfb24
else
    check "vfb reloaded at 24 bpp" false
fi

echo "== $first: a missing framebuffer"
"$first" run --display fbdev:/dev/fb7 --input none --board /t/board.toml --frames 10 < /dev/null > /out/fb7.log 2>&1
rc=$?
cat /out/fb7.log
check "missing /dev/fb7: exit status not 0" [ "$rc" != 0 ]
check "missing /dev/fb7: one sentence naming it" is_sentence "$(last_line /out/fb7.log)" "/dev/fb7"

echo "guest checks failed: $FAILS"
exit "$FAILS"
