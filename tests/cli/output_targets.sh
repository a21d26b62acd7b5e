#!/usr/bin/env bash
# Output never replaces what is not a regular file (docs/reliability.md, "Files the program does
# not own"). For each of --out, --gif, --record and --screenshot:
#  - a device node (a copy of /dev/null made with mknod, as root; /dev/null itself otherwise), a
#    directory, a symbolic link to a file, a dangling one and a socket are refused before the run:
#    one sentence, exit 2, the thing left exactly as it was, nothing left beside it;
#  - a FIFO with a reader, and standard output by the name /dev/stdout, are written into; a FIFO
#    nothing reads is one sentence, not a wait;
#  - a replaced file keeps its permissions (0600 stays 0600, 0640 stays 0640).
# Then the temporary files: a writer killed by SIGKILL leaves its temporary file, and the next
# write of the same target removes it; a live writer's (locked) and a user's own hidden file of a
# similar name are left alone.
#   output_targets.sh NONEUCLID
set -uo pipefail
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
trap 'kill $(jobs -p) 2> /dev/null; rm -rf "$tmp"' EXIT

# cmd: the command that writes FILE through OPTION (one of the four), small and quick.
command_for() {
    case "$1" in
        --out) cmd=("$noneuclid" render --scene fig1 --frames 1 --size 64x64 --out "$2") ;;
        --gif) cmd=("$noneuclid" render --scene fig1 --frames 2 --size 64x64 --gif "$2") ;;
        --record) cmd=("$noneuclid" run --display png --scene fig1 --frames 2 --size 64x64 --record "$2" --screenshot shot.png) ;;
        --screenshot) cmd=("$noneuclid" run --display png --scene fig1 --frames 2 --size 64x64 --screenshot "$2") ;;
    esac
}
# What a path is, without following a link: its type, device numbers, size, mode and link target.
describe() { stat -c '%F %t:%T %s %a %i' "$1" 2>/dev/null; readlink "$1"; }
# The first bytes a file of OPTION's kind starts with.
magic() {
    case "$1" in
        --out | --screenshot) printf '\211PNG' ;;
        --gif) printf 'GIF89a' ;;
        --record) printf '# noneuclid' ;;
    esac
}
starts_with() { [ "$(head -c "${#2}" "$1" 2>/dev/null)" = "$2" ]; }

# refused NAME OPTION PATH: exit 2, one line naming PATH, PATH as it was, nothing beside it.
refused() {
    local name=$1 option=$2 path=$3 before rc=0
    before=$(describe "$path")
    command_for "$option" "$path"
    timeout 60 "${cmd[@]}" > out.txt 2> err.txt || rc=$?
    if [ "$rc" != 2 ]; then fail "$name: exit $rc, not 2: $(cat err.txt)"; return; fi
    if [ "$(wc -l < err.txt)" != 1 ] || ! grep -q -- "^noneuclid: $option: cannot write $path: it is .*, not a regular file, and is left alone: give the path of " err.txt; then
        fail "$name: not the one sentence: $(cat err.txt)"; return
    fi
    if [ "$(describe "$path")" != "$before" ]; then fail "$name: $path changed: $(describe "$path")"; return; fi
    if compgen -G "$(dirname "$path")/.$(basename "$path").*" > /dev/null; then fail "$name: a temporary file is left"; return; fi
    pass "$name: $(cut -c1-120 err.txt)"
}

echo "the file a link points to" > target.txt
mkdir dir
ln -s target.txt link
ln -s nowhere dangling
device=/dev/null
if [ "$(id -u)" = 0 ]; then
    mknod null c 1 3 && device=$tmp/null  # never /dev/null itself as root: a failure would replace it
fi
socket=
if command -v python3 > /dev/null &&
    python3 -c 'import socket,sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' sock 2> /dev/null; then
    socket=sock
fi
for option in --out --gif --record --screenshot; do
    refused "$option a device ($device)" "$option" "$device"
    refused "$option a directory" "$option" dir
    refused "$option a symbolic link" "$option" link
    refused "$option a dangling symbolic link" "$option" dangling
    [ -n "$socket" ] && refused "$option a socket" "$option" "$socket"
done
if [ "$(cat target.txt)" = "the file a link points to" ]; then pass "the links' target untouched"; else fail "target.txt changed"; fi
if [ -e nowhere ]; then fail "the dangling link's target was made"; else pass "the dangling link's target not made"; fi
[ -n "$socket" ] || echo "SKIP sockets: no python3 to make one"

# Written into: a FIFO with a reader, and /dev/stdout (a pipe here).
for option in --out --gif --record --screenshot; do
    # (The reader may not have opened the FIFO yet when the program looks for one: then the
    # program rightly finds none, the reader is let go by an empty write, and the case runs again.)
    for attempt in 1 2 3 4 5; do
        rm -f fifo got && mkfifo fifo
        cat fifo > got &
        reader=$!
        rc=0
        command_for "$option" fifo
        timeout 60 "${cmd[@]}" > /dev/null 2> err.txt || rc=$?
        if [ "$rc" != 0 ] && grep -q "that nothing reads" err.txt; then
            : > fifo
            wait "$reader"
            sleep "0.$attempt"
            continue
        fi
        wait "$reader"
        break
    done
    if [ "$rc" = 0 ] && [ -p fifo ] && starts_with got "$(magic "$option")"; then pass "$option a FIFO with a reader: written into"
    else fail "$option a FIFO with a reader: exit $rc, fifo $(describe fifo), got $(head -c 12 got | od -c | head -1): $(cat err.txt)"; fi

    rm -f fifo && mkfifo fifo
    rc=0
    command_for "$option" fifo
    timeout 60 "${cmd[@]}" > /dev/null 2> err.txt || rc=$?
    if [ "$rc" != 0 ] && [ "$rc" != 124 ] && [ -p fifo ] && grep -q "cannot write fifo: it is a pipe (FIFO) that nothing reads: start its reader first" err.txt; then
        pass "$option a FIFO nothing reads: exit $rc, not waited on"
    else fail "$option a FIFO nothing reads: exit $rc (124: it waited): $(cat err.txt)"; fi
done
for option in --out --gif; do
    command_for "$option" /dev/stdout
    timeout 60 "${cmd[@]}" 2> err.txt | cat > piped
    rc=${PIPESTATUS[0]}
    if [ "$rc" = 0 ] && starts_with piped "$(magic "$option")"; then pass "$option /dev/stdout into a pipe"
    else fail "$option /dev/stdout: $(cat err.txt)"; fi
done

# A replaced file keeps its permissions.
for option in --out --gif --record --screenshot; do
    for mode in 600 640; do
        case $option in --gif) ext=gif ;; --record) ext=rec ;; *) ext=png ;; esac  # (the name each writes)
        name=kept${option#--}$mode.$ext
        echo "an earlier file" > "$name" && chmod "$mode" "$name"
        command_for "$option" "$name"
        "${cmd[@]}" > /dev/null 2> err.txt
        if [ "$(stat -c %a "$name")" = "$mode" ] && starts_with "$name" "$(magic "$option")"; then pass "$option keeps mode $mode"
        else fail "$option: mode $(stat -c %a "$name"), not $mode: $(cat err.txt)"; fi
    done
done

# Temporary files: A writes rec.txt for as long as it runs. B writes it meanwhile: A's temporary
# file (locked: its writer lives) stays. A killed by SIGKILL leaves it; C's write removes it, but
# not a user's .rec.txt.backup nor a temporary file another live process holds locked.
leftovers() { compgen -G '.rec.txt.noneuclid-*' | sort; }
"$noneuclid" run --display png --scene fig1 --frames 100000000 --size 64x64 --record rec.txt --screenshot a.png 2> a.txt &
a=$!
for _ in $(seq 600); do [ -n "$(leftovers)" ] && break; sleep 0.05; done
a_temp=$(leftovers)
if [ -z "$a_temp" ]; then
    fail "the long writer made no temporary file: $(cat a.txt)"
else
    "$noneuclid" run --display png --scene fig1 --frames 2 --size 64x64 --record rec.txt --screenshot b.png 2> b.txt
    if [ -e "$a_temp" ] && grep -q "^frames 2$" rec.txt; then pass "a live writer's temporary file is left to it"
    else fail "B removed A's temporary file, or wrote no recording: $(cat b.txt)"; fi
    kill -KILL "$a"
    wait "$a" 2> /dev/null
    if [ -e "$a_temp" ]; then pass "SIGKILL leaves the temporary file"; else fail "the killed writer left nothing (it should have)"; fi
    echo "mine" > .rec.txt.backup
    echo "held" > .rec.txt.noneuclid-HELDxx
    exec 9< .rec.txt.noneuclid-HELDxx && flock -x 9  # held by this shell while C runs
    "$noneuclid" run --display png --scene fig1 --frames 3 --size 64x64 --record rec.txt --screenshot c.png 2> c.txt
    if [ ! -e "$a_temp" ] && grep -q "^frames 3$" rec.txt; then pass "the next write removed the killed writer's temporary file"
    else fail "the killed writer's temporary file is still there: $(leftovers): $(cat c.txt)"; fi
    if [ -e .rec.txt.backup ]; then pass "a user's own .rec.txt.backup left alone"; else fail "removed .rec.txt.backup"; fi
    if [ -e .rec.txt.noneuclid-HELDxx ]; then pass "a locked temporary file left alone"; else fail "removed a locked temporary file"; fi
    exec 9<&-
fi

[ "$failures" = 0 ] || { echo "$failures failed" >&2; exit 1; }
