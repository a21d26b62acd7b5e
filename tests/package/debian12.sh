# shellcheck shell=bash
# A clean Debian 12 booted with systemd in a container, for tests/package/package-test (sourced
# from it). Needs root: debootstrap, chroot, systemd-nspawn.
#
#   d12_base DIR          the pristine tree, made once with debootstrap (minbase and systemd)
#                         from the mirror apt already uses, and kept in DIR (a second run
#                         reuses it; delete DIR to start afresh)
#   d12_fresh BASE ROOT   ROOT := a copy of BASE
#   d12_boot ROOT LOG     boots ROOT (systemd-nspawn --boot; the console goes to LOG) and waits
#                         until systemd has finished starting up
#   ct CMD...             runs CMD in the booted container as root (plain environment, no stdin)
#   ct_write PATH         writes its standard input to PATH in the container
#   d12_stop              powers the container off (also on exit, by d12_cleanup)
#   d12_manifest ROOT     what a package can leave behind in ROOT, one line each, sorted: every
#                         path outside the caches, logs and apt's and dpkg's databases, with its
#                         type, mode and owner; a checksum of each file in /etc; and the lines
#                         of the user and group databases

d12_say() { echo "package: $*" >&2; }

# The Debian archive apt already uses (deb822 .sources or one-line .list), else deb.debian.org;
# NONEUCLID_DEBIAN_MIRROR overrides it.
d12_mirror() {
    if [ -n "${NONEUCLID_DEBIAN_MIRROR:-}" ]; then
        echo "$NONEUCLID_DEBIAN_MIRROR"
        return
    fi
    local url
    url=$(cat /etc/apt/sources.list.d/*.sources 2>/dev/null |
          sed -n 's/^URIs:[[:space:]]*//p' | tr ' ' '\n' | grep -E '/debian/?$' | head -n 1 || true)
    [ -n "$url" ] || url=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
          sed -n 's/^deb[[:space:]]\+\(\[[^]]*\][[:space:]]\+\)\?\([^[:space:]]*\/debian\/\?\)[[:space:]].*/\2/p' |
          head -n 1 || true)
    echo "${url:-http://deb.debian.org/debian}"
}

d12_base() {
    local base=$1
    [ -x "$base/usr/lib/systemd/systemd" ] && [ -f "$base/.noneuclid-complete" ] && return 0
    local mirror
    mirror=$(d12_mirror)
    d12_say "making a Debian 12 tree with debootstrap from $mirror into $base (once; about two minutes)"
    rm -rf --one-file-system "$base"
    mkdir -p "$(dirname "$base")"
    # minbase and systemd: dpkg, apt and an init that runs units, nothing else.
    debootstrap --variant=minbase --include=systemd bookworm "$base" "$mirror" >"$base.log" 2>&1 || {
        tail -n 30 "$base.log" >&2
        d12_say "debootstrap failed (the last lines of $base.log above)"
        return 1
    }
    # Apt inside follows the host's settings (e.g. a snapshot mirror whose Release is past its
    # Valid-Until date), and the downloaded packages are not kept in the tree.
    cp /etc/apt/apt.conf.d/* "$base/etc/apt/apt.conf.d/" 2>/dev/null || true
    rm -f "$base"/var/cache/apt/archives/*.deb
    touch "$base/.noneuclid-complete"
}

d12_fresh() {
    rm -rf --one-file-system "$2"
    cp -a "$1" "$2"
}

CT_NSPAWN=""
CT_INIT=""
d12_boot() {
    local root=$1 log=$2 _
    systemd-nspawn --quiet --register=no --keep-unit --machine=noneuclid-package-test \
        --directory="$root" --boot --console=pipe </dev/null >"$log" 2>&1 &
    CT_NSPAWN=$!
    # The container's init: nspawn's child, once it has become systemd.
    for _ in $(seq 300); do
        CT_INIT=$(pgrep -P "$CT_NSPAWN" | head -n 1 || true)
        [ -n "$CT_INIT" ] && [ "$(cat "/proc/$CT_INIT/comm" 2>/dev/null)" = systemd ] && break
        CT_INIT=""
        kill -0 "$CT_NSPAWN" 2>/dev/null || break
        sleep 0.1
    done
    if [ -z "$CT_INIT" ]; then
        cat "$log" >&2
        d12_say "systemd-nspawn could not boot $root (its output above)"
        return 1
    fi
    # Until systemd answers (its socket comes a moment after it starts), then until it has
    # started everything.
    local state="" _
    for _ in $(seq 600); do
        state=$(timeout 120 nsenter -t "$CT_INIT" -a systemctl is-system-running --wait 2>&1 || true)
        case $state in
            *"Failed to connect"*|offline) sleep 0.1 ;;
            *) break ;;
        esac
    done
    case $state in
        running|degraded) ;;
        *)  d12_say "the container did not finish booting (systemctl is-system-running: $state)"
            return 1 ;;
    esac
}

ct() {
    nsenter -t "$CT_INIT" -a -r -w env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
        DEBIAN_FRONTEND=noninteractive "$@" </dev/null
}

ct_write() {
    # shellcheck disable=SC2016  # $1 is the inner shell's
    nsenter -t "$CT_INIT" -a -r -w sh -c 'cat >"$1"' sh "$1"
}

d12_stop() {
    [ -n "$CT_NSPAWN" ] || return 0
    if kill -0 "$CT_NSPAWN" 2>/dev/null; then
        if [ -n "$CT_INIT" ]; then
            nsenter -t "$CT_INIT" -a systemctl poweroff >/dev/null 2>&1 || true
        fi
        local _
        for _ in $(seq 300); do
            kill -0 "$CT_NSPAWN" 2>/dev/null || break
            sleep 0.1
        done
        kill -KILL "$CT_NSPAWN" 2>/dev/null || true
    fi
    wait "$CT_NSPAWN" 2>/dev/null || true
    CT_NSPAWN=""
}
d12_cleanup() { d12_stop; }

d12_manifest() {
    local root=$1
    (
        cd "$root" || exit 1
        find . -xdev \( -path ./proc -o -path ./sys -o -path ./dev -o -path ./run -o -path ./tmp \
            -o -path ./var/tmp -o -path ./var/log -o -path ./var/cache -o -path ./var/lib/apt \
            -o -path ./var/lib/dpkg -o -path ./var/lib/systemd -o -path ./root \) -prune \
            -o -printf '%p %y %m %u %g\n'
        # dpkg's per-package files, and deb-systemd-helper's record of enable links.
        find ./var/lib/dpkg/info ./var/lib/systemd/deb-systemd-helper-* -printf '%p %y %m %u %g\n' 2>/dev/null
        find ./etc -xdev -type f ! -name passwd ! -name group ! -name shadow ! -name gshadow \
            ! -name '*-' -exec md5sum {} +
        local db
        for db in passwd group shadow gshadow; do
            # The date of the last password change (shadow's third field) is the day's.
            sed "s/^/$db: /" "etc/$db" | sed 's/^\(shadow: [^:]*:[^:]*:\)[0-9]*:/\1DAY:/'
        done
    ) | sort
}
