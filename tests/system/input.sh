# shellcheck shell=dash
# (busybox sh, an ash, runs it; shellcheck 0.9 checks ash as dash.)
# Guest script of tests/system/input-test (busybox sh in the VM, helpers from guest-lib.sh):
# the kiosk's input backends against a real kernel, through `noneuclid buttons`.
# /t/params.sh sets BINARIES (static noneuclid builds in /t, e.g. "noneuclid-gpiod1
# noneuclid-gpiod2": the libgpiod v1 and v2 backends); /t/board.toml is the VM's board
# (tests/system/board.toml: chip "noneuclid-sim", thrust on line 0, left 1, right 2,
# curvature_up 3, reset 6, fire 8; 5 ms debounce).
#
# For each binary, on the gpio-sim chip:
#   describe   the start-up line names the chip, 9 buttons, the libgpiod API and the debounce
#   sequence   presses and releases of two buttons, in order
#   held       (gpio-sim cannot hold a line against the request's pull-up: informational)
#   debounce   with a 200 ms debounce, five fast edges then a hold give one press (and with 0 ms
#              the same bounce reaches the program as several, so the bounce was real)
#   busy       a second program asking for held lines fails with the busy-line sentence
#   no chip    a board naming a chip that is not there: the sentence lists what is
#   no line    a line beyond the chip's 9: the sentence gives the range
#   alloc      read() allocates nothing while lines change (input_alloc_probe, malloc wrapped)
# Once (the evdev code is the same in every binary), through a uinput key device:
#   evdev      a key held at start (a press first), press/release, an autorepeat (ignored), release; grabbed
#   no keys    a board whose codes no device has: the sentence names the codes
# And as a user outside the gpio and input groups: the permission sentences.

# Written by the host for this run (tests/system/run, input-test).
# shellcheck source=/dev/null
. /t/params.sh
BOARD=/t/board.toml
NBUTTONS=$(grep -c '^gpio = ' "$BOARD")

check "gpio-sim chip noneuclid-sim live" sim_chip noneuclid-sim 9
echo "gpio-sim: $SIM_DEV"

# listen NAME BINARY ARGS...: `BINARY buttons ARGS` in the background (stdout /out/NAME.txt,
# stderr /out/NAME.log), PID in LPID; true once it has opened its input (its start-up line).
listen() {
    _name=$1 _bin=$2
    shift 2
    "$_bin" buttons "$@" > "/out/$_name.txt" 2> "/out/$_name.log" &
    LPID=$!
    wait_for "/out/$_name.log" "^noneuclid: (gpio|evdev): " "$LPID"
}
# finish: wait for the listener; its exit status in LRC.
finish() {
    wait "$LPID"
    LRC=$?
}
# board_with SED_EXPR FILE: a variant of the VM's board.
board_with() { sed "$1" "$BOARD" > "$2"; }

for bin in $BINARIES; do
    case $bin in
        *gpiod2*) api="(v2 API)" deb=kernel ;;
        *) api="(v1 API)" deb=software ;;
    esac

    # sequence (and describe)
    if listen "$bin-sequence" "$bin" --board "$BOARD" --input gpio --events 4 --timeout 20; then
        sim_pull 0 pull-down; sleep 0.2
        sim_pull 0 pull-up; sleep 0.2
        sim_pull 2 pull-down; sleep 0.2
        sim_pull 2 pull-up
    fi
    finish
    check "$bin sequence: exit 0" [ "$LRC" = 0 ]
    check "$bin sequence: press/release thrust, press/release right" [ "$(cat "/out/$bin-sequence.txt")" = "press thrust
release thrust
press right
release right" ]
    check "$bin describe: chip, buttons, API, debounce" contains "$(cat "/out/$bin-sequence.log")" \
        "gpio: noneuclid-sim ($SIM_DEV), $NBUTTONS buttons, libgpiod " "$api, $deb debounce 5 ms"

    # held at start: gpio-sim cannot model it. Its lines have one pull, which the program's
    # pull-up request sets (gpio_sim_set_config), so a line "held" before the request reads
    # released after it; a real button to ground overrides the SoC's weak pull-up. The
    # initial-level path is covered by the evdev case below (EVIOCGKEY) and the unit tests.
    sim_pull 1 pull-down
    listen "$bin-held" "$bin" --board "$BOARD" --input gpio --timeout 0.5
    echo "INFO $bin line 1 pulled down before the request reads $(sim_value 1) after it (gpio-sim: the request's pull-up wins)"
    finish
    sim_pull 1 pull-up
    check "$bin held-at-start (not modelled): no spurious event" [ ! -s "/out/$bin-held.txt" ]

    # debounce: 200 ms; a five-edge bounce ending pressed, held 0.6 s, released
    board_with 's/^debounce_ms = .*/debounce_ms = 200/' /tmp/board-200.toml
    listen "$bin-debounce" "$bin" --board /tmp/board-200.toml --input gpio --timeout 2 && {
        sim_pull 3 pull-down; sim_pull 3 pull-up; sim_pull 3 pull-down; sim_pull 3 pull-up; sim_pull 3 pull-down
        sleep 0.6
        sim_pull 3 pull-up
    }
    finish
    check "$bin debounce: exit 0 at the timeout" [ "$LRC" = 0 ]
    check "$bin debounce: one press, one release" [ "$(cat "/out/$bin-debounce.txt")" = "press curvature_up
release curvature_up" ]
    # The control: no debounce, the same bounce (informational: the edges may merge in the kernel).
    board_with 's/^debounce_ms = .*/debounce_ms = 0/' /tmp/board-0.toml
    listen "$bin-nodebounce" "$bin" --board /tmp/board-0.toml --input gpio --timeout 1 && {
        sim_pull 3 pull-down; sim_pull 3 pull-up; sim_pull 3 pull-down; sim_pull 3 pull-up; sim_pull 3 pull-down
        sleep 0.3
        sim_pull 3 pull-up
    }
    finish
    echo "INFO $bin without debounce the bounce gave $(grep -c '^press' "/out/$bin-nodebounce.txt") presses"

    # busy: a first listener holds the lines, a second asks for them
    if listen "$bin-holder" "$bin" --board "$BOARD" --input gpio --timeout 30; then
        holder=$LPID
        "$bin" buttons --board "$BOARD" --input gpio --events 1 --timeout 2 > /dev/null 2> "/out/$bin-busy.log"
        rc=$?
        kill "$holder"
        wait "$holder"
        check "$bin busy: exit 2" [ "$rc" = 2 ]
        check "$bin busy: the sentence" contains "$(cat "/out/$bin-busy.log")" \
            "GPIO line 0 (thrust, header pin 11) on noneuclid-sim ($SIM_DEV) is in use by \"noneuclid\": stop that program"
    else
        check "$bin busy: the first listener started" false
    fi

    # read() allocates nothing: input_alloc_probe (malloc wrapped) reads lines 0-3 for 3 s
    # while each is pressed and released, twice over for lines 0 and 1 (12 events)
    probe=/t/input_alloc_probe-${bin#noneuclid-}
    if [ -x "$probe" ]; then
        "$probe" gpio noneuclid-sim 3 > "/out/$bin-alloc.txt" 2>&1 &
        ppid=$!
        if wait_for "/out/$bin-alloc.txt" '^ready$' "$ppid"; then
            for l in 0 1 2 3 0 1; do
                sim_pull "$l" pull-down; sleep 0.1
                sim_pull "$l" pull-up; sleep 0.1
            done
        fi
        wait "$ppid"
        rc=$?
        result=$(tail -n 1 "/out/$bin-alloc.txt")
        check "$bin gpio read() allocates nothing ($result)" [ "$rc" = 0 ]
        check "$bin gpio allocation probe saw the 12 events" [ "$result" = "events 12 allocations 0" ]
    else
        echo "INFO $bin: no allocation probe"
    fi

    # no chip
    board_with 's/^chip = .*/chip = ["no-such-chip", "pinctrl-bcm2711"]/' /tmp/board-nochip.toml
    "$bin" buttons --board /tmp/board-nochip.toml --input gpio --timeout 2 > /dev/null 2> "/out/$bin-nochip.log"
    check "$bin no chip: exit 2" [ "$?" = 2 ]
    check "$bin no chip: the sentence" contains "$(cat "/out/$bin-nochip.log")" \
        "no GPIO chip matches no-such-chip, pinctrl-bcm2711 (the chips here are $SIM_DEV \"noneuclid-sim\"): run \`gpiodetect\`"

    # no line: reset moved from line 6 to 20
    board_with 's/^gpio = 6$/gpio = 20/' /tmp/board-noline.toml
    "$bin" buttons --board /tmp/board-noline.toml --input gpio --timeout 2 > /dev/null 2> "/out/$bin-noline.log"
    check "$bin no line: exit 2" [ "$?" = 2 ]
    check "$bin no line: the sentence" contains "$(cat "/out/$bin-noline.log")" \
        "GPIO line 20 (reset" "does not exist on noneuclid-sim ($SIM_DEV), which has 9 lines (0 to 8)"
done

# permission: a user outside the gpio group (devtmpfs makes the chip root's, mode 0600)
mkdir -p /etc
grep -q '^kiosk:' /etc/passwd 2>/dev/null || echo "kiosk:x:1000:1000::/tmp:/bin/sh" >> /etc/passwd
bin=${BINARIES%% *}
chmod 600 "$SIM_DEV"
su -s /bin/sh -c "$bin buttons --board $BOARD --input gpio --timeout 2" kiosk > /dev/null 2> /out/perm-gpio.log
check "gpio permission: exit 2" [ "$?" = 2 ]
check "gpio permission: the sentence" contains "$(cat /out/perm-gpio.log)" \
    "no permission to open $SIM_DEV (looking for the GPIO chip noneuclid-sim): add the user to the gpio group (\`sudo usermod -aG gpio \$USER\`) and log in again"

# evdev through uinput: a key device with KEY_UP (thrust) and KEY_LEFT (left)
bin=${BINARIES%% *}
check "evdev.ko loaded" insmod /t/evdev.ko
mkfifo /tmp/keys
uinput-inject noneuclid-keys 103 105 < /tmp/keys > /tmp/inject.out 2>&1 &
inject=$!
exec 3> /tmp/keys
if wait_for /tmp/inject.out '^ready$' "$inject"; then
    sleep 0.3    # devtmpfs makes /dev/input/eventN
    echo "p 105" >&3
    sleep 0.2
    if listen evdev "$bin" --board "$BOARD" --input evdev --events 4 --timeout 20; then
        echo "p 103" >&3; sleep 0.1
        echo "a 103" >&3; sleep 0.1
        echo "r 103" >&3; sleep 0.1
        echo "r 105" >&3
    fi
    finish
    check "evdev: exit 0" [ "$LRC" = 0 ]
    check "evdev: held left, thrust pressed, repeat ignored, released" [ "$(cat /out/evdev.txt)" = "press left
press thrust
release thrust
release left" ]
    probe=/t/input_alloc_probe-${bin#noneuclid-}
    if [ -x "$probe" ]; then
        "$probe" evdev 2 > /out/evdev-alloc.txt 2>&1 &
        ppid=$!
        if wait_for /out/evdev-alloc.txt '^ready$' "$ppid"; then
            for k in 103 105 103; do
                echo "p $k" >&3; sleep 0.1
                echo "r $k" >&3; sleep 0.1
            done
        fi
        wait "$ppid"
        rc=$?
        result=$(tail -n 1 /out/evdev-alloc.txt)
        check "evdev read() allocates nothing ($result)" [ "$rc" = 0 ]
        check "evdev allocation probe saw the 6 events" [ "$result" = "events 6 allocations 0" ]
    fi
    check "evdev describe: the device, grabbed" contains "$(cat /out/evdev.log)" "evdev: /dev/input/event" \
        "\"noneuclid-keys\"" ", grabbed"
else
    check "uinput device created" false
fi
# permission: the same user, outside the input group
chmod 600 /dev/input/event*
su -s /bin/sh -c "$bin buttons --board $BOARD --input evdev --timeout 2" kiosk > /dev/null 2> /out/perm-evdev.log
check "evdev permission: exit 2" [ "$?" = 2 ]
check "evdev permission: the sentence" contains "$(cat /out/perm-evdev.log)" \
    "no permission to open /dev/input/event0 (looking for a device with the key codes " \
    "): add the user to the input group (\`sudo usermod -aG input \$USER\`) and log in again"
# no keys: a board whose only code (BTN_TRIGGER_HAPPY1, an arcade encoder's) no device has
# (the VM also has an AT keyboard)
board_with '/^key = /d; /^action = "thrust"/a key = 704' /tmp/board-nokeys.toml
"$bin" buttons --board /tmp/board-nokeys.toml --input evdev --timeout 2 > /dev/null 2> /out/evdev-nokeys.log
check "evdev no keys: exit 2" [ "$?" = 2 ]
check "evdev no keys: the sentence" contains "$(cat /out/evdev-nokeys.log)" \
    "no input device has any of the key codes 704 (looked at " "\"noneuclid-keys\""
echo q >&3
exec 3>&-
wait "$inject"

exit "$FAILS"
