#!/usr/bin/env bash
# `cpack -G DEB` with the configuration of a build directory that installs under PREFIX (not
# /usr): it must stop with the reason and make no package, however it is asked.
#   cpack_needs_usr.sh CPackConfig.cmake PREFIX
set -uo pipefail
config=$1 prefix=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
out=$(cpack -G DEB --config "$config" -B "$tmp" 2>&1)
rc=$?
echo "$out"
if [ "$rc" = 0 ]; then echo "FAIL cpack succeeded" >&2; exit 1; fi
want="noneuclid: this build directory installs under $prefix, and a Debian package installs under /usr"
if [[ $(tr '\n' ' ' <<< "$out" | tr -s ' ') != *"$want"* ]]; then echo "FAIL cpack did not say why" >&2; exit 1; fi
if [ -n "$(find "$tmp" -name '*.deb')" ]; then echo "FAIL a package was made" >&2; exit 1; fi
echo "PASS cpack -G DEB refused, exit $rc, no package"
