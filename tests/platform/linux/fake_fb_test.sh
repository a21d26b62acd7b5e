#!/usr/bin/env bash
# The kiosk against framebuffers reporting geometries no sane driver reports (fake_fb.cpp,
# preloaded, answers the framebuffer ioctls for a plain file): every bad value is refused with
# one sentence and exit 2 before anything is written; good ones run and draw into the file.
#   fake_fb_test.sh NONEUCLID FAKE_FB_SHIM
set -uo pipefail
noneuclid=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shim=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fb=$tmp/fb
failures=0

# case NAME "XRES YRES XOFF YOFF XVIRT YVIRT BPP LINE SMEM" FILE_BYTES STATUS [LAST_LINE_PART]
case_() {
    local name=$1 geometry=$2 bytes=$3 want=$4 part=${5:-} rc=0
    rm -f "$fb" && truncate -s "$bytes" "$fb"
    FAKE_FB=$fb FAKE_FB_GEOMETRY=$geometry LD_PRELOAD=$shim \
        ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 \
        timeout 60 "$noneuclid" run --display "fbdev:$fb" --input none --board generic --frames 3 \
        < /dev/null > "$tmp/out" 2> "$tmp/err" || rc=$?
    local last
    last=$(tail -n 1 "$tmp/err")
    if [ "$rc" != "$want" ]; then
        echo "FAIL $name: exit $rc, not $want:" >&2; cat "$tmp/err" >&2; failures=$((failures + 1)); return
    fi
    if [ -n "$part" ]; then
        case $last in
            "noneuclid: "*"$part"*.) ;;
            *) echo "FAIL $name: the last line is not one sentence with '$part': $last" >&2; failures=$((failures + 1)); return ;;
        esac
    elif [ "$(tr -d '\000' < "$fb" | head -c 1 | wc -c)" = 0 ]; then
        echo "FAIL $name: nothing was drawn into the framebuffer" >&2; failures=$((failures + 1)); return
    fi
    echo "PASS $name${part:+: $last}"
}

case_ "good: 320x240, 32 bits"          "320 240 0 0 320 240 32 1280 307200" 307200 0
case_ "good: 320x240, 16 bits, padded lines" "320 240 0 0 320 240 16 1024 245760" 245760 0
case_ "good: an offset inside the memory" "320 240 16 8 400 300 32 1600 480000" 480000 0
case_ "x offset 400 on an 800-pixel line" "800 480 400 0 800 480 32 3200 1536000" 1536000 2 "rows (with their x offset) longer than a line"
case_ "x offset 100000"                  "800 480 100000 0 800 480 32 3200 1536000" 1536000 2 "rows (with their x offset) longer than a line"
case_ "y offset past the memory"         "800 480 0 1000 800 480 32 3200 1536000" 1536000 2 "past the end of its memory"
case_ "y offset 4294967295"              "800 480 0 4294967295 800 480 32 3200 1536000" 1536000 2 "past the end of its memory"
case_ "a line shorter than a row"        "800 480 0 0 800 480 32 1000 1536000" 1536000 2 "rows (with their x offset) longer than a line"
case_ "memory smaller than the rows"     "800 480 0 0 800 480 32 3200 1000" 1536000 2 "past the end of its memory"
case_ "an empty mode"                    "0 480 0 0 0 480 32 3200 1536000" 1536000 2 "an empty mode"
case_ "a mode of 100000 pixels a side"   "100000 100000 0 0 100000 100000 32 400000 4000000000" 4096 2 "larger than 16384 pixels a side"
case_ "a line of 4 GiB"                  "800 480 0 0 800 480 32 4294967295 4294967295" 4096 2 "a line length over 256 MiB"

[ "$failures" = 0 ] || { echo "$failures failed" >&2; exit 1; }
