#!/usr/bin/env bash
# The high-score table from the command line (docs/reliability.md, "Files the program does not
# own"): `noneuclid scores` and `noneuclid run --scores` on what the game did not write (a text
# file, a directory, a device node, a FIFO, a symbolic link to a file and a dangling one): one
# sentence, exit 2, the thing left exactly as it was, nothing renamed, nothing of a file's text
# shown. A table of the game's own that is damaged: `scores` says so and leaves it (its control
# characters never printed raw); `run` sets it aside, and a second damaged table goes beside the
# first, which stays as it was. The state directory's table that is not the game's: `run` plays on
# without keeping scores, the file untouched.
#   scores_files.sh NONEUCLID
set -uo pipefail
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
describe() { stat -c '%F %t:%T %s %a %i %Y' "$1" 2>/dev/null; readlink "$1"; }
listing() { timeout 60 "$noneuclid" scores --scores "$1"; }
playing() { timeout 60 "$noneuclid" run --display png --scene asteroids --frames 2 --size 64x64 --screenshot shot.png --scores "$1"; }
header='# noneuclid high scores: score, level reached, when (UTC)'

# refused NAME PATH SAYS: both commands exit 2 with one sentence containing SAYS, PATH as it was,
# nothing made beside it, and no SECRET in what they printed.
refused() {
    local name=$1 path=$2 says=$3 before command rc
    before=$(describe "$path")
    for command in listing playing; do
        rc=0
        "$command" "$path" > out.txt 2> all.txt || rc=$?
        grep -v '^noneuclid: display png, because ' all.txt > err.txt  # run's line saying which display
        if [ "$rc" != 2 ]; then fail "$command $name: exit $rc, not 2: $(cat err.txt)"; continue; fi
        if ! grep -q -- "$says" err.txt || [ "$(grep -c . err.txt)" != 1 ]; then fail "$command $name: not the one sentence: $(cat err.txt)"; continue; fi
        if grep -q SECRET out.txt err.txt; then fail "$command $name: showed the file's text: $(cat err.txt)"; continue; fi
        if [ "$(describe "$path")" != "$before" ]; then fail "$command $name: $path changed"; continue; fi
        if compgen -G "$path.*" > /dev/null; then fail "$command $name: made $(compgen -G "$path.*")"; continue; fi
        pass "$command $name: $(cut -c1-110 err.txt)"
    done
}

printf 'SECRET notes\n1200 2 2026-11-25T14:03:11Z\n' > notes.txt
printf 'root:SECRET:19000:0:99999:7:::\n' > secret
ln -s secret link
ln -s nowhere dangling
mkdir dir
mkfifo fifo
device=/dev/null
if [ "$(id -u)" = 0 ]; then
    mknod null c 1 3 && device=$tmp/null  # never /dev/null itself as root: a failure would rename it
fi
refused "a text file" notes.txt "it is not a high-score table the game wrote"
refused "a symbolic link" link "it is a symbolic link, not a regular file"
refused "a dangling symbolic link" dangling "it is a symbolic link, not a regular file"
refused "a directory" dir "it is a directory, not a regular file"
refused "a FIFO" fifo "it is a pipe (FIFO), not a regular file"
if [ "$device" != /dev/null ] || [ "$(id -u)" != 0 ]; then  # (as root, only a copy: see above)
    refused "a device ($device)" "$device" "it is a device, not a regular file"
fi
if [ -e nowhere ]; then fail "the dangling link's target was made"; else pass "nothing made where the dangling link points"; fi

# A damaged table of the game's own, with an escape sequence and a bell in it.
damaged=$(printf '%s\n100 1 2026-11-25T14:03:11Z\n50 1 \033[2J\007\n' "$header")
printf '%s\n' "$damaged" > table
rc=0
listing table > out.txt 2> err.txt || rc=$?
if [ "$rc" = 2 ] && grep -q "is damaged (line 3 is not a score" err.txt && [ "$(cat table)" = "$damaged" ] &&
    ! compgen -G 'table.*' > /dev/null; then pass "scores: a damaged table is said to be damaged and left where it is"
else fail "scores on a damaged table: exit $rc: $(cat err.txt)"; fi
if LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' out.txt err.txt; then fail "a control character printed raw: $(od -c err.txt | head)"
else pass "no control character printed raw"; fi

rc=0
playing table > out.txt 2> err.txt || rc=$?
if [ "$rc" = 0 ] && grep -q "it is set aside as 'table.damaged'" err.txt && [ "$(cat table.damaged)" = "$damaged" ] && [ ! -e table ]; then
    pass "run: a damaged table set aside as table.damaged"
else fail "run on a damaged table: exit $rc: $(cat err.txt)"; fi
second=$(printf '%s\n7 1 2026-11-25T14:03:11Z\n8 1 2026-11-25T14:03:11Z\n' "$header")
printf '%s\n' "$second" > table
rc=0
playing table > out.txt 2> err.txt || rc=$?
if [ "$rc" = 0 ] && grep -q "set aside as 'table.damaged.2'" err.txt && [ "$(cat table.damaged.2)" = "$second" ] &&
    [ "$(cat table.damaged)" = "$damaged" ]; then pass "run: a second damaged table goes beside the first, which stays"
else fail "run on a second damaged table: exit $rc: $(cat err.txt)"; fi

# A good table is listed, and its listing leaves it as it was.
printf '%s\n1230 3 2026-11-25T14:03:11Z\n400 1 2026-11-24T09:00:00Z\n' "$header" > good
before=$(describe good)
rc=0
listing good > out.txt 2> err.txt || rc=$?
if [ "$rc" = 0 ] && grep -q "^ 1      1230  level 3    2026-11-25T14:03:11Z$" out.txt && [ "$(describe good)" = "$before" ]; then
    pass "scores lists a good table and leaves it"
else fail "scores on a good table: exit $rc: $(cat out.txt err.txt)"; fi

# The state directory's table (no --scores) that is not the game's: the kiosk plays on.
mkdir state && cp notes.txt state/scores
rc=0
STATE_DIRECTORY=$tmp/state timeout 60 "$noneuclid" run --display png --scene asteroids --frames 2 --size 64x64 \
    --screenshot shot.png > out.txt 2> err.txt || rc=$?
if [ "$rc" = 0 ] && grep -q "the high scores are not kept: the high-score table .* it is not a high-score table the game wrote" err.txt &&
    cmp -s notes.txt state/scores && [ "$(ls state)" = scores ]; then pass "run with the state directory's foreign table plays on, the file untouched"
else fail "run with a foreign state table: exit $rc: $(cat err.txt)"; fi

[ "$failures" = 0 ] || { echo "$failures failed" >&2; exit 1; }
