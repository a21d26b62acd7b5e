#!/usr/bin/env bash
# Output is written whole or not at all, and a failed write is one sentence and a non-zero exit:
#  - standard output on a full disk (/dev/full): dump, accuracy, --help;
#  - a file-size limit (RLIMIT_FSIZE, as a full disk) while writing a PNG (render, demo, run's
#    screenshot), an animated GIF (render --gif, and into a missing directory) or a recording:
#    the existing file is left as it was, no temporary file remains;
#  - SIGTERM while the world runs, and SIGINT while the PNG is written: the same.
#   output_safety.sh NONEUCLID
set -uo pipefail
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
# expect NAME STATUS STDERR_PART COMMAND...: the exit status and one line naming the problem.
expect() {
    local name=$1 want=$2 part=$3 rc=0
    shift 3
    "$@" > out.txt 2> err.txt || rc=$?
    if [ "$rc" != "$want" ]; then fail "$name: exit $rc, not $want: $(cat err.txt)"; return; fi
    if ! grep -q -- "$part" err.txt; then fail "$name: stderr lacks '$part': $(cat err.txt)"; return; fi
    pass "$name"
}
# intact NAME FILE: FILE is still the good copy, and no temporary file is left beside it.
intact() {
    if ! cmp -s "$2" "$2.good"; then fail "$1: $2 was changed"; return; fi
    local left
    if left=$(compgen -G ".$2.*"); then fail "$1: a temporary file is left: $left"; return; fi
    pass "$1: $2 untouched, nothing left behind"
}
# stopped NAME PID SIGNAL STDERR_PATTERN: sends SIGNAL to the background command PID (its stderr
# in err.txt), which must exit 1 with a line matching the pattern.
stopped() {
    local rc=0
    kill "-$3" "$2"
    wait "$2" || rc=$?
    if [ "$rc" = 1 ] && grep -q "$4" err.txt; then pass "$1"; else fail "$1: exit $rc: $(cat err.txt)"; fi
}

expect "dump --frames 0 > /dev/full" 1 "cannot write the dump to standard output (No space left on device)" \
    sh -c "\"$noneuclid\" dump --frames 0 > /dev/full"
expect "dump --frames 1000 > /dev/full" 1 "cannot write the dump to standard output" \
    sh -c "\"$noneuclid\" dump --frames 1000 > /dev/full"
expect "accuracy > /dev/full" 1 "cannot write to standard output (No space left on device)" \
    sh -c "\"$noneuclid\" accuracy --samples 2 --random 0 > /dev/full"
expect "--help > /dev/full" 1 "cannot write to standard output" sh -c "\"$noneuclid\" --help > /dev/full"

"$noneuclid" render --scene fig14 --frames 10 --out pic.png 2>/dev/null && cp pic.png pic.png.good
expect "render over the file-size limit" 1 "cannot write pic.png: File too large" \
    prlimit --fsize=2000 "$noneuclid" render --scene fig1 --out pic.png
intact "render over the file-size limit" pic.png

"$noneuclid" render --scene stress --frames 100000 --out pic.png 2> err.txt &
pid=$!
sleep 1
stopped "SIGTERM while the world runs" "$pid" TERM "stopped by signal 15 after .* frames; pic.png is left as it was"
intact "SIGTERM while the world runs" pic.png

# A picture big enough to take seconds to write; the signal comes while it is written.
"$noneuclid" render --scene fig1 --frames 0 --size 8192x8192 --format rgb565 --out pic.png 2> err.txt &
pid=$!
for _ in $(seq 400); do compgen -G '.pic.png.*' >/dev/null && break; sleep 0.05; done
stopped "SIGINT while the PNG is written" "$pid" INT "stopped by signal 2 while writing pic.png; it is left as it was"
intact "SIGINT while the PNG is written" pic.png

echo "an earlier recording" > rec.txt && cp rec.txt rec.txt.good
expect "recording over the file-size limit" 1 "the recording: cannot write rec.txt: File too large" \
    prlimit --fsize=300 "$noneuclid" run --display png --frames 100 --record rec.txt --screenshot shot.png
intact "recording over the file-size limit" rec.txt

"$noneuclid" render --scene fig1 --frames 4 --size 160x120 --gif anim.gif 2>/dev/null && cp anim.gif anim.gif.good
expect "render --gif over the file-size limit" 1 "cannot write anim.gif: File too large" \
    prlimit --fsize=3000 "$noneuclid" render --scene fig1 --frames 120 --gif anim.gif
intact "render --gif over the file-size limit" anim.gif
# A missing folder is made (app/setup.hpp, check_output); one that cannot be made is one sentence.
expect "render --gif into a folder that cannot be made" 2 "--gif: cannot make the folder 'anim.gif/deeper'" \
    "$noneuclid" render --scene fig1 --frames 4 --gif anim.gif/deeper/anim.gif
intact "render --gif into a folder that cannot be made" anim.gif
"$noneuclid" render --scene fig1 --frames 4 --size 160x120 --gif made/deeper/anim.gif 2>/dev/null
if [ -s made/deeper/anim.gif ]; then pass "render --gif into a missing folder: made"; else fail "render --gif made/deeper/anim.gif: not written"; fi

mkdir -p demo && "$noneuclid" demo --out-dir demo > /dev/null 2>&1
cp demo/kiosk.png kiosk.png.good
expect "demo over the file-size limit" 1 "cannot write demo/kiosk.png: File too large" \
    prlimit --fsize=3000 "$noneuclid" demo --out-dir demo
(cd demo && cp ../kiosk.png.good . && intact "demo over the file-size limit" kiosk.png)

[ "$failures" = 0 ] || { echo "$failures failed" >&2; exit 1; }
