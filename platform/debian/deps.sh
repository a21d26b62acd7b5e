#!/bin/sh
# Install the Debian packages named as arguments, but only those not yet installed.
#
#   platform/debian/deps.sh g++ cmake make          # run it
#   . platform/debian/deps.sh; noneuclid_deps g++   # or source it and call the function
#   noneuclid_foreign_archs arm64; noneuclid_deps libgpiod-dev:arm64   # multiarch packages
#
# Runs apt-get as root, through sudo otherwise; never prompts; runs `apt-get update` only when
# something is missing, so a second run with everything present does nothing.

noneuclid_deps() {
    _nd_missing=""
    for _nd_pkg in "$@"; do
        case $(dpkg-query -W -f='${Status}' "$_nd_pkg" 2>/dev/null) in
            *"install ok installed"*) ;;
            *) _nd_missing="$_nd_missing $_nd_pkg" ;;
        esac
    done
    [ -z "$_nd_missing" ] && return 0

    if [ "$(id -u)" -eq 0 ]; then
        _nd_sudo=""
    elif command -v sudo >/dev/null 2>&1; then
        _nd_sudo="sudo"
    else
        echo "deps.sh: missing Debian packages; as root, run: apt-get install$_nd_missing" >&2
        return 1
    fi

    echo "deps.sh: installing$_nd_missing" >&2
    if [ -z "${_nd_updated:-}" ]; then
        $_nd_sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q </dev/null || return 1
    fi
    # shellcheck disable=SC2086  # word splitting of the package list is intended
    $_nd_sudo env DEBIAN_FRONTEND=noninteractive \
        apt-get install -y -q --no-install-recommends $_nd_missing </dev/null
}

# Enable the foreign architectures named (e.g. arm64 armhf) for multiarch packages such as
# libgpiod-dev:arm64, which noneuclid_deps then installs. Only those not enabled yet: then
# `dpkg --add-architecture` and one `apt-get update`, so a second run does nothing.
noneuclid_foreign_archs() {
    _nd_new=""
    for _nd_arch in "$@"; do
        [ "$_nd_arch" = "$(dpkg --print-architecture)" ] && continue
        dpkg --print-foreign-architectures | grep -qx "$_nd_arch" || _nd_new="$_nd_new $_nd_arch"
    done
    [ -z "$_nd_new" ] && return 0

    if [ "$(id -u)" -eq 0 ]; then
        _nd_sudo=""
    elif command -v sudo >/dev/null 2>&1; then
        _nd_sudo="sudo"
    else
        echo "deps.sh: architectures not enabled; as root, run: dpkg --add-architecture for each of$_nd_new, then apt-get update" >&2
        return 1
    fi
    echo "deps.sh: enabling the architectures$_nd_new" >&2
    for _nd_arch in $_nd_new; do
        $_nd_sudo dpkg --add-architecture "$_nd_arch" || return 1
    done
    # A failed index (a mirror mid-sync) need not stop the install: it fails by itself if
    # the packages wanted really cannot be found.
    $_nd_sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q </dev/null ||
        echo "deps.sh: apt-get update reported errors (above); trying to install anyway" >&2
    _nd_updated=1    # noneuclid_deps need not update again in this shell
}

# Run as a program (not sourced): install the arguments and exit with the result.
case ${0##*/} in
    deps.sh) noneuclid_deps "$@"; exit $? ;;
esac
