#!/usr/bin/env bash
# `run-demo --web PORT` on a port another program listens on: one sentence that names the port
# and how to choose another, exit status 2, no traceback, and no wait (it stops before the
# build and the server). Run by tests/web/run, where the web packages are installed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
work=$(mktemp -d)
trap 'kill "$holder" 2>/dev/null || true; rm -rf "$work"' EXIT
# A listener on a free port the kernel picks; it writes the port, then waits.
python3 -c 'import socket, sys, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen()
open(sys.argv[1], "w").write(str(s.getsockname()[1])); time.sleep(120)' "$work/port" &
holder=$!
for _ in $(seq 100); do [ -s "$work/port" ] && break; sleep 0.1; done
port=$(cat "$work/port")
status=0
timeout 60 platform/debian/run-demo --web "$port" >"$work/out" 2>"$work/err" || status=$?
fail() { echo "not ok - run-demo --web on busy port $port: $1"; cat "$work/out" "$work/err"; exit 1; }
[ "$status" -eq 2 ] || fail "exit status $status, not 2"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "not one line on stderr"
grep -q "port $port .*busy.*--web $((port + 1))" "$work/err" || fail "the sentence does not say the port is busy and how to choose another"
! grep -q 'Traceback\|open http' "$work/out" "$work/err" || fail "it printed a traceback or an address to open"
echo "ok - run-demo --web on busy port $port: one sentence, exit status 2"
