#!/bin/sh
# Install the Debian packages named as arguments, but only those not yet installed.
#
#   platform/debian/deps.sh g++ cmake make          # run it
#   . platform/debian/deps.sh; noneuclid_deps g++   # or source it and call the function
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
    # shellcheck disable=SC2086  # word splitting of the package list is intended
    $_nd_sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q </dev/null &&
        $_nd_sudo env DEBIAN_FRONTEND=noninteractive \
            apt-get install -y -q --no-install-recommends $_nd_missing </dev/null
}

# Run as a program (not sourced): install the arguments and exit with the result.
case ${0##*/} in
    deps.sh) noneuclid_deps "$@"; exit $? ;;
esac
