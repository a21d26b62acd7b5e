#!/bin/sh
# Install the Debian packages named as arguments, but only those not yet installed.
#
#   platform/debian/deps.sh g++ cmake make          # run it
#   . platform/debian/deps.sh; noneuclid_deps g++   # or source it and call the function
#   noneuclid_foreign_archs arm64; noneuclid_deps libgpiod-dev:arm64   # multiarch packages
#   noneuclid_apt_update                             # `apt-get update`, as below
#
# Runs apt-get as root, through sudo otherwise; never prompts; runs `apt-get update` only when
# something is missing, so a second run with everything present does nothing.
#
# A mirror is not always whole: `apt-get update` can fail for one index (a security mirror
# mid-sync: "File has unexpected size ... Mirror sync in progress?") while every package wanted
# is still there, and a download can fail once and work a minute later. So an update error never
# stops anything by itself: the update is tried twice, then the install goes ahead and is the
# judge. A failed install is tried once more after another update; only if that fails too does
# noneuclid_deps fail, naming the packages still missing in one sentence.
# (tests/deps/deps-test checks this logic against a fake apt-get; tests/deps/deps-system-test
# against the real one, with a deliberately broken apt source.)

# Sets _nd_sudo to "" (root) or "sudo"; 1 if neither is possible.
_nd_as_root() {
    if [ "$(id -u)" -eq 0 ]; then
        _nd_sudo=""
    elif command -v sudo >/dev/null 2>&1; then
        _nd_sudo="sudo"
    else
        return 1
    fi
}

# apt-get with the options every call here wants: no questions, no stdin, and a wait (rather
# than a failure) while another apt or dpkg (e.g. unattended-upgrades on a fresh machine's first
# boot) holds the lock.
_nd_apt() {
    $_nd_sudo env DEBIAN_FRONTEND=noninteractive \
        apt-get -q -o DPkg::Lock::Timeout=300 "$@" </dev/null
}

# `apt-get update`, tried twice; always returns 0 (a failed index is reported, not fatal: the
# install that follows fails by itself if a package it needs really cannot be found).
noneuclid_apt_update() {
    _nd_as_root || {
        echo "deps.sh: cannot run apt-get update: not root and no sudo" >&2
        return 0
    }
    _nd_updated=1    # noneuclid_deps need not update again in this shell
    _nd_apt update && return 0
    echo "deps.sh: apt-get update reported errors (above); trying it once more in ${NONEUCLID_APT_RETRY_DELAY:-10} s" >&2
    sleep "${NONEUCLID_APT_RETRY_DELAY:-10}"
    _nd_apt update && return 0
    echo "deps.sh: apt-get update reported errors again (above); installing anyway" >&2
    return 0
}

# The arguments that are not installed, space-separated with a leading space.
_nd_missing_of() {
    _nd_m=""
    for _nd_pkg in "$@"; do
        case $(dpkg-query -W -f='${Status}' "$_nd_pkg" 2>/dev/null) in
            *"install ok installed"*) ;;
            *) _nd_m="$_nd_m $_nd_pkg" ;;
        esac
    done
    echo "$_nd_m"
}

noneuclid_deps() {
    _nd_missing=$(_nd_missing_of "$@")
    [ -z "$_nd_missing" ] && return 0

    _nd_as_root || {
        echo "deps.sh: missing Debian packages; as root, run: apt-get install$_nd_missing" >&2
        return 1
    }

    echo "deps.sh: installing$_nd_missing" >&2
    [ -n "${_nd_updated:-}" ] || noneuclid_apt_update
    # shellcheck disable=SC2086  # word splitting of the package list is intended
    _nd_apt install -y --no-install-recommends $_nd_missing && return 0

    # A download that failed (a flaky mirror), or package lists older than the mirror: fresh
    # lists, and once more.
    echo "deps.sh: apt-get install failed (above); updating the package lists and trying once more" >&2
    noneuclid_apt_update
    # shellcheck disable=SC2086  # as above
    _nd_apt install -y --no-install-recommends $_nd_missing && return 0

    _nd_missing=$(_nd_missing_of "$@")
    _nd_unknown=""
    for _nd_pkg in $_nd_missing; do
        case $(apt-cache policy "$_nd_pkg" 2>/dev/null) in
            *"Candidate: "[0-9]*) ;;
            *) _nd_unknown="$_nd_unknown $_nd_pkg" ;;
        esac
    done
    if [ -n "$_nd_unknown" ]; then
        echo "deps.sh: could not install$_nd_missing (apt-get install failed twice, output above; no installable version of$_nd_unknown in the configured apt sources)" >&2
    else
        echo "deps.sh: could not install$_nd_missing (apt-get install failed twice, output above)" >&2
    fi
    return 1
}

# Enable the foreign architectures named (e.g. arm64 armhf) for multiarch packages such as
# libgpiod-dev:arm64, which noneuclid_deps then installs. Only those not enabled yet: then
# `dpkg --add-architecture` and one noneuclid_apt_update, so a second run does nothing.
noneuclid_foreign_archs() {
    _nd_new=""
    for _nd_arch in "$@"; do
        [ "$_nd_arch" = "$(dpkg --print-architecture)" ] && continue
        dpkg --print-foreign-architectures | grep -qx "$_nd_arch" || _nd_new="$_nd_new $_nd_arch"
    done
    [ -z "$_nd_new" ] && return 0

    _nd_as_root || {
        echo "deps.sh: architectures not enabled; as root, run: dpkg --add-architecture for each of$_nd_new, then apt-get update" >&2
        return 1
    }
    echo "deps.sh: enabling the architectures$_nd_new" >&2
    for _nd_arch in $_nd_new; do
        $_nd_sudo dpkg --add-architecture "$_nd_arch" || return 1
    done
    noneuclid_apt_update
}

# Run as a program (not sourced): install the arguments and exit with the result.
case ${0##*/} in
    deps.sh) noneuclid_deps "$@"; exit $? ;;
esac
