# shellcheck shell=bash
# What the command-line test scripts share, sourced with the script's own arguments: `noneuclid`
# (the program, $1, as an absolute path), a temporary working directory `tmp` removed at exit
# (the script may set its own EXIT trap after), and the PASS/FAIL tally in `failures`.
# shellcheck disable=SC2034 # (noneuclid and failures are the sourcing script's to use)
noneuclid=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0
fail() { echo "FAIL $*" >&2; failures=$((failures + 1)); }
pass() { echo "PASS $*"; }
