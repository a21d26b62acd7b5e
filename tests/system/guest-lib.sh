# shellcheck shell=dash
# (busybox sh, an ash, runs it; shellcheck 0.9 checks ash as dash.)
# Helpers for guest scripts of tests/system/run (busybox sh inside the VM). /init sources this
# file before running the guest script, so its functions are already defined there.
#
#   sim_chip LABEL NLINES   one gpio-sim chip with one bank of NLINES lines labelled LABEL,
#                           made live, every line pulled up (active-low buttons: released);
#                           sets SIM_DIR (the lines' sysfs directory) and SIM_DEV (/dev/gpiochipN)
#   sim_pull N pull-up|pull-down    drive line N (pull-down = button pressed)
#   sim_value N             the line's current value (0/1) as gpio-sim sees it
#   fb_by_name NAME         /dev/fbN whose /sys/class/graphics/fbN/name is NAME
#   fb_dump /dev/fbN BASE   BASE.raw: the visible rows (line_length bytes each, from yoffset),
#                           BASE.info: the probe line (format, stride, offsets) for the host
#   check WHAT CONDITION... `check "fb0 is bochs" [ "$x" = y ]`: prints PASS/FAIL WHAT, counts
#                           failures in FAILS (the guest script's exit status should be $FAILS)
#   contains TEXT PART...   true if TEXT contains every PART
#   wait_for FILE REGEX PID until FILE matches the extended REGEX (true), or PID exits or 20 s
#                           pass (false)
#
# /out/ is copied back to the host; /t/ holds the files the host passed in.

FAILS=0

check() {
    _what=$1
    shift
    if "$@"; then
        echo "PASS $_what"
    else
        echo "FAIL $_what"
        FAILS=$((FAILS + 1))
    fi
}

contains() {
    _text=$1
    shift
    for _part in "$@"; do
        case $_text in
            *"$_part"*) ;;
            *) return 1 ;;
        esac
    done
}

wait_for() {
    _i=0
    while [ "$_i" -lt 200 ]; do
        grep -qE "$2" "$1" 2>/dev/null && return 0
        kill -0 "$3" 2>/dev/null || return 1
        sleep 0.1
        _i=$((_i + 1))
    done
    return 1
}

sim_chip() {
    _cfg=/sys/kernel/config/gpio-sim/chip0
    mkdir "$_cfg" "$_cfg/bank0" || return 1
    echo "$2" > "$_cfg/bank0/num_lines" || return 1
    echo "$1" > "$_cfg/bank0/label" || return 1
    echo 1 > "$_cfg/live" || return 1
    # shellcheck disable=SC2034  # for the guest scripts, which run after this file is sourced
    SIM_DEV=/dev/$(cat "$_cfg/bank0/chip_name")
    SIM_DIR=/sys/devices/platform/$(cat "$_cfg/dev_name")/$(cat "$_cfg/bank0/chip_name")
    _n=0
    while [ "$_n" -lt "$2" ]; do
        sim_pull "$_n" pull-up || return 1
        _n=$((_n + 1))
    done
}

sim_pull() { echo "$2" > "$SIM_DIR/sim_gpio$1/pull"; }
sim_value() { cat "$SIM_DIR/sim_gpio$1/value"; }

fb_by_name() {
    for _fb in /sys/class/graphics/fb[0-9]*; do
        if [ "$(cat "$_fb/name" 2>/dev/null)" = "$1" ]; then
            echo "/dev/${_fb##*/}"
            return 0
        fi
    done
    return 1
}

fb_dump() {
    probe fb "$1" > "$2.info" || return 1
    _stride=$(sed -n 's/.* line_length=\([0-9]*\) .*/\1/p' "$2.info")
    _yres=$(sed -n 's/.* yres=\([0-9]*\) .*/\1/p' "$2.info")
    _yoff=$(sed -n 's/.* yoffset=\([0-9]*\) .*/\1/p' "$2.info")
    dd if="$1" of="$2.raw" bs="$_stride" skip="$_yoff" count="$_yres" 2>/dev/null
}
