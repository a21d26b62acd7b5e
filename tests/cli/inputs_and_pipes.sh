#!/usr/bin/env bash
# Small truths from the command line (docs/reliability.md):
#  - a font named as a FIFO (--font, NONEUCLID_FONT, a recording's `font` line) is refused or
#    passed over at once, never waited on (each command runs under a timeout: 124 is a wait);
#  - a NUL or a control byte inside an actions file's time word is refused with its line;
#  - `noneuclid dump | head` ends with the sentence and status the docs give for a closed pipe,
#    not a silent SIGPIPE (141).
#   inputs_and_pipes.sh NONEUCLID
set -uo pipefail
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
# expect NAME STATUS STDERR_PART COMMAND...
expect() {
    local name=$1 want=$2 part=$3 rc=0
    shift 3
    timeout 60 "$@" > out.txt 2> err.txt || rc=$?
    if [ "$rc" != "$want" ]; then fail "$name: exit $rc, not $want (124: it waited): $(cat err.txt)"; return; fi
    if ! grep -qF -- "$part" err.txt; then fail "$name: stderr lacks '$part': $(cat err.txt)"; return; fi
    pass "$name"
}

mkfifo font.psf
expect "--font a FIFO" 2 "font.psf: the font file is a pipe (FIFO), not a file (it is not waited on)" \
    "$noneuclid" render --scene fig1 --frames 1 --size 64x64 --hud --font font.psf --out a.png
expect "NONEUCLID_FONT a FIFO" 0 "wrote a.png" \
    env NONEUCLID_FONT="$tmp/font.psf" "$noneuclid" render --scene fig1 --frames 1 --size 64x64 --hud --out a.png
printf 'scene fig1\nfont %s\n0 press thrust\n' "$tmp/font.psf" > rec.txt
expect "a recording's font a FIFO" 2 "font.psf: the font file is a pipe (FIFO), not a file (it is not waited on)" \
    "$noneuclid" render --actions rec.txt --frames 1 --size 64x64 --out a.png

printf '0.5\0junk press thrust\n' > nul.txt
expect "a NUL in a time word" 2 "nul.txt:1: expected a time in seconds (a number >= 0) or a setting" \
    "$noneuclid" dump --actions nul.txt --frames 1
if grep -qF "found '0.5\\x00junk'" err.txt; then pass "the NUL shown escaped"; else fail "the NUL not shown escaped: $(cat err.txt)"; fi
printf '1\033[2J press thrust\n' > esc.txt
expect "an escape in a time word" 2 "esc.txt:1: expected a time in seconds" "$noneuclid" dump --actions esc.txt --frames 1
printf '1.5\vpress thrust\n' > vt.txt
expect "a vertical tab between words" 2 "vt.txt:1: a control character ('\\x0b') where only spaces and tabs may part words" \
    "$noneuclid" dump --actions vt.txt --frames 1

rc=0
timeout 60 "$noneuclid" dump --scene kiosk --frames 100000 2> err.txt | head -c 100 > /dev/null
rc=${PIPESTATUS[0]}
if [ "$rc" = 1 ] && [ "$(cat err.txt)" = "noneuclid: cannot write the dump to standard output (Broken pipe): check where it goes." ]; then
    pass "dump | head: the sentence and exit 1"
else fail "dump | head: exit $rc (141: SIGPIPE), stderr: $(cat err.txt)"; fi

[ "$failures" = 0 ] || { echo "$failures failed" >&2; exit 1; }
