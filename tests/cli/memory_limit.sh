#!/usr/bin/env bash
# Under a memory limit (ulimit -v, RLIMIT_AS), a request too large for it is one sentence and
# exit status 2, with nothing left behind: no new file, no temporary file, an existing file as
# it was (issue 33: render --size 16384x16384 and a large --gif died by SIGABRT, the GIF's
# temporary file left). The same limit lets an ordinary render through, so it is the size, not
# the limit, that is refused.
#   memory_limit.sh NONEUCLID
# Exit 77 (skipped) where the limit cannot be set or the program cannot start under it (a
# sanitizer build reserves terabytes of address space).
set -uo pipefail
noneuclid=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
limit=$((768 << 20))  # bytes of address space: the program, its libraries and threads fit
limited() { prlimit --as=$limit:$limit -- "$@"; }
if ! limited "$noneuclid" --version > /dev/null 2>&1; then
    echo "SKIP: noneuclid does not start under a $((limit >> 20)) MiB address-space limit (a sanitizer build?)"
    exit 77
fi
failures=0
fail() { echo "FAIL $*" >&2; failures=$((failures + 1)); }
pass() { echo "PASS $*"; }
# refused NAME COMMAND...: exit 2, a last line saying out of memory and the fix (run says which
# display it chose first), nothing new in the directory, keep.png and keep.gif as they were.
refused() {
    local name=$1 rc=0
    shift
    limited "$@" > out.txt 2> err.txt || rc=$?
    if [ "$rc" != 2 ]; then fail "$name: exit $rc, not 2: $(head -c 400 err.txt)"; return; fi
    if [ "$(grep -c . err.txt)" -gt 2 ] || ! tail -n 1 err.txt | grep -q "^noneuclid: out of memory: .*use a smaller --size"; then
        fail "$name: not the one sentence: $(head -c 400 err.txt)"
        return
    fi
    local f left=""
    for f in * .[!.]*; do
        case $f in out.txt | err.txt | keep.png | keep.png.good | keep.gif | keep.gif.good | '*' | '.[!.]*') ;; *) left="$left $f" ;; esac
    done
    if [ -n "$left" ]; then fail "$name: left behind:$left"; return; fi
    if ! cmp -s keep.png keep.png.good; then fail "$name: keep.png was changed"; return; fi
    if ! cmp -s keep.gif keep.gif.good; then fail "$name: keep.gif was changed"; return; fi
    pass "$name"
}
limited "$noneuclid" render --frames 2 --size 320x200 --out keep.png > /dev/null 2>&1 || fail "an ordinary render under the limit"
cp keep.png keep.png.good
echo "an earlier file" > keep.gif && cp keep.gif keep.gif.good
refused "render --size 16384x16384" "$noneuclid" render --frames 1 --size 16384x16384 --out big.png
refused "render over an existing file" "$noneuclid" render --frames 1 --size 16384x16384 --out keep.png
# The GIF's buffers fit and its temporary file is open when the canvas does not: it goes too.
refused "render --gif at 10000x10000" "$noneuclid" render --frames 2 --size 10000x10000 --gif big.gif
refused "render --gif over an existing file" "$noneuclid" render --frames 2 --size 10000x10000 --gif keep.gif
refused "render --gif at 16384x16384" "$noneuclid" render --frames 2 --size 16384x16384 --gif big.gif
refused "run --display png at 16384x16384" "$noneuclid" run --display png --frames 1 --size 16384x16384 --screenshot shot.png
# Under 30 MiB the threads' stacks may not fit: then the sentence and exit 2, never a signal.
rc=0
prlimit --as=$((30 << 20)) -- "$noneuclid" run --display png --frames 2 --threads 4 --size 320x200 \
    --screenshot shot.png > out.txt 2> err.txt || rc=$?
if [ "$rc" = 0 ] || { [ "$rc" = 2 ] && tail -n 1 err.txt | grep -q "^noneuclid: cannot start a thread (.*): use fewer --threads"; }; then
    pass "run --threads 4 under 30 MiB (exit $rc)"
else
    fail "run --threads 4 under 30 MiB: exit $rc: $(head -c 400 err.txt)"
fi
rm -f shot.png
[ "$failures" = 0 ]
