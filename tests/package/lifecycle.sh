# shellcheck shell=bash
# shellcheck disable=SC2154  # $work, $version and $host_build are package-test's
# The amd64 package's life on a clean Debian 12 booted with systemd (step 4 of
# tests/package/package-test, sourced from it; uses its ok, bad, check, depends_names, $work,
# $version and $host_build): install an older build, run, enable, upgrade, remove, purge, and
# what is left behind.

# The package as an older build: the same files, the version VERSION~older (which dpkg orders
# before VERSION), so that installing the real one is an upgrade.
older_build() {
    local new=$1 out=$2 tree=$work/older
    rm -rf "$tree"
    dpkg-deb -R "$new" "$tree"
    sed -i "s/^Version: .*/Version: $version~older/" "$tree/DEBIAN/control"
    dpkg-deb --root-owner-group -Zxz -b "$tree" "$out" >/dev/null
}

# wait_for SECONDS CMD...: until CMD succeeds; false when the time is up.
wait_for() {
    local tenths=$(($1 * 10))
    shift
    until "$@" 2>/dev/null; do
        tenths=$((tenths - 1))
        [ "$tenths" -gt 0 ] || return 1
        sleep 0.1
    done
}

# Predicates on the container.
journal_has() { ct journalctl -u noneuclid -o cat --no-pager | grep -q -F -e "$1"; }
is_active() { [ "$(ct systemctl is-active noneuclid)" = "$1" ]; }
# Not running, nor on its way up or down. (Stopped by a signal, the kiosk exits with status 1, so
# systemd may say failed rather than inactive.)
stopped() { case $(ct systemctl is-active noneuclid) in inactive|failed) true ;; *) false ;; esac; }
main_pid() { ct systemctl show -p MainPID --value noneuclid; }
in_groups() {
    local have g
    have=" $(ct id -nG noneuclid) "
    for g in "$@"; do [[ $have == *" $g "* ]] || return 1; done
}
unit_verifies() {
    local out
    if out=$(ct systemd-analyze verify --man=no /usr/lib/systemd/system/noneuclid.service 2>&1) && [ -z "$out" ]; then
        return 0
    fi
    echo "$out" >&2
    return 1
}
# The uids journald filed for the program's own lines (those it could name): exactly $1.
journal_uids_are() {
    [ "$(ct journalctl -u noneuclid _COMM=noneuclid -o export --no-pager | sed -n 's/^_UID=//p' | sort -u)" = "$1" ]
}
restarted() { [ "$(ct systemctl show -p NRestarts --value noneuclid)" -ge 1 ]; }
runs_as() {  # runs_as PID UID GID...: the process's real uid and supplementary groups
    local status g
    status=$(ct cat "/proc/$1/status") || return 1
    grep -q -P "^Uid:\t$2\t" <<<"$status" || return 1
    shift 2
    for g in "$@"; do grep -q -E "^Groups:.*\b$g\b" <<<"$status" || return 1; done
}
# The high-score table in the state directory, read by the program as the service would.
kept_scores() {
    ct runuser -u noneuclid -- env STATE_DIRECTORY=/var/lib/noneuclid noneuclid scores |
        grep -q -E '^ *1 +4200 +level 3 +2026-01-02T03:04:05Z$'
}
has_env() { ct cat "/proc/$1/environ" | tr '\0' '\n' | grep -q -x -F -e "$2"; }
new_pid() { local p; p=$(main_pid); [ "$p" != 0 ] && [ "$p" != "$1" ]; }
gone() { local p; for p in "$@"; do ! ct test -e "$p" || return 1; done; }
user_exists() { ct id noneuclid >/dev/null; }
no_user() { ! ct getent passwd noneuclid >/dev/null && ! ct getent group noneuclid >/dev/null; }
no_links() { [ -z "$(ct find /etc/systemd -name 'noneuclid*')" ]; }

lifecycle() {
    local new_deb=$1 root=$work/root
    echo "== amd64 on Debian 12 with systemd (a container: tests/package/lifecycle.sh)"
    d12_base "$work/debian12" || { bad "debootstrap makes a Debian 12 tree (above)"; return; }
    d12_fresh "$work/debian12" "$root"
    older_build "$new_deb" "$root/root/noneuclid_older.deb"
    cp "$new_deb" "$root/root/noneuclid.deb"
    trap d12_cleanup EXIT
    local t0=$SECONDS
    d12_boot "$root" "$work/console.log" || { bad "Debian 12 boots with systemd in a container (above)"; return; }
    ok "Debian 12 booted with systemd in a container in $((SECONDS - t0)) s"

    # What the package needs, from the archive (downloads kept in build/package-test/archives),
    # then the tree as it is before the package.
    mkdir -p "$work/archives"
    cp "$work"/archives/*.deb "$root/var/cache/apt/archives/" 2>/dev/null || true
    ct apt-get -q -o Dpkg::Use-Pty=0 update >"$work/apt.log" 2>&1 || true
    # shellcheck disable=SC2046  # one word per package
    if ! ct apt-get -q -y -o Dpkg::Use-Pty=0 --no-install-recommends install $(depends_names "$new_deb") \
        >>"$work/apt.log" 2>&1; then
        tail -n 20 "$work/apt.log" >&2
        bad "the package's dependencies install from the archive (the end of $work/apt.log above)"
        return
    fi
    cp "$root"/var/cache/apt/archives/*.deb "$work/archives/" 2>/dev/null || true
    d12_manifest "$root" >"$work/before.txt"

    # -- install (the older build) and run
    if ! ct dpkg -i /root/noneuclid_older.deb >"$work/install.log" 2>&1; then
        cat "$work/install.log" >&2
        bad "dpkg -i installs the package (its output above)"
        return
    fi
    ok "dpkg -i installs the package (the older build, $version~older)"
    check "the user noneuclid is in the groups video, input, gpio and audio" in_groups video input gpio audio
    check "the user has no shell, and /var/lib/noneuclid as home" \
        [ "$(ct getent passwd noneuclid | cut -d: -f6,7)" = /var/lib/noneuclid:/usr/sbin/nologin ]
    check "/var/lib/noneuclid belongs to noneuclid" [ "$(ct stat -c '%U:%G %a' /var/lib/noneuclid)" = "noneuclid:noneuclid 755" ]
    check "systemd-analyze verify has nothing to say about the unit" unit_verifies
    check "the unit is installed, not enabled and not started" \
        [ "$(ct systemctl is-enabled noneuclid) $(ct systemctl is-active noneuclid)" = "disabled inactive" ]
    check "noneuclid --version says $version" [ "$(ct noneuclid --version)" = "noneuclid $version" ]
    local render=(render --scene kiosk --frames 90 --aa --hud --font builtin --size 480x320)
    ct noneuclid "${render[@]}" --out /root/render.png >/dev/null 2>&1 || true
    "$host_build/noneuclid" "${render[@]}" --out "$work/render-host.png" >/dev/null 2>&1
    check "noneuclid render on Debian 12 draws the host build's picture, pixel for pixel" \
        "$host_build/png_diff" "$root/root/render.png" "$work/render-host.png" --exact

    # -- enabled: the kiosk as the unit starts it. A container has no virtual console, so a
    # runtime drop-in (in /run, gone with the container) gives it no terminal instead of
    # /dev/tty1; and no framebuffer, which the kiosk says, and systemd starts it again.
    ct mkdir -p /run/systemd/system/noneuclid.service.d
    ct_write /run/systemd/system/noneuclid.service.d/10-no-console.conf <<'UNIT'
[Service]
StandardInput=null
TTYReset=no
TTYVHangup=no
UNIT
    ct systemctl daemon-reload
    ct systemctl enable --now noneuclid >/dev/null 2>&1
    check "enabled, the unit runs the kiosk, which finds no framebuffer and says so" \
        wait_for 20 journal_has "there is no framebuffer /dev/fb0"
    check "the kiosk reads /etc/noneuclid/board.toml over its board" journal_has "/etc/noneuclid/board.toml is read over it"
    local uid
    uid=$(ct id -u noneuclid)
    # journald reads a line's _COMM from /proc when it files the line; a kiosk that has already
    # exited leaves its lines without one. Restart=always brings it back, so wait for a line
    # filed while the kiosk lived rather than trusting the first start's timing.
    check "the kiosk ran as noneuclid (uid $uid)" wait_for 30 journal_uids_are "$uid"
    check "systemd starts it again when it stops (Restart=always)" wait_for 10 restarted

    # Then a kiosk that keeps running: the headless display (small: it is not paced), through a
    # second drop-in, its picture kept in the state directory.
    ct_write /run/systemd/system/noneuclid.service.d/20-headless.conf <<'UNIT'
[Service]
ExecStart=
ExecStart=/bin/sh -c 'exec /usr/bin/noneuclid run --display png --size 64x64 --frames 100000000 --screenshot "$${STATE_DIRECTORY}/last.png"'
UNIT
    ct systemctl daemon-reload
    ct systemctl reset-failed noneuclid
    ct systemctl restart noneuclid
    check "the kiosk keeps running on the headless display" wait_for 10 is_active active
    local pid gids="" g
    pid=$(main_pid)
    for g in video input gpio audio; do gids="$gids $(ct getent group "$g" | cut -d: -f3)"; done
    # shellcheck disable=SC2086  # one word per group id
    check "the running kiosk has the user's uid and the groups video, input, gpio and audio (gids$gids)" runs_as "$pid" "$uid" $gids
    check "the kiosk is given STATE_DIRECTORY=/var/lib/noneuclid" has_env "$pid" STATE_DIRECTORY=/var/lib/noneuclid
    # The user's state (a high-score table with a game in it, as the kiosk would have written
    # it) and board override, which an upgrade must keep.
    ct runuser -u noneuclid -- sh -c 'printf "# noneuclid high scores\n4200 3 2026-01-02T03:04:05Z\n" >/var/lib/noneuclid/scores'
    ct sh -c 'printf "\n[attract]\nidle_seconds = 300\n" >>/etc/noneuclid/board.toml'

    # -- upgrade
    if ! ct dpkg -i /root/noneuclid.deb >"$work/upgrade.log" 2>&1; then
        cat "$work/upgrade.log" >&2
        bad "dpkg -i upgrades the package (its output above)"
        return
    fi
    # shellcheck disable=SC2016  # ${Version} is dpkg-query's
    check "dpkg -i upgrades $version~older to $version" [ "$(ct dpkg-query -W -f='${Version}' noneuclid)" = "$version" ]
    check "the upgrade restarted the enabled kiosk" wait_for 10 new_pid "$pid"
    check "the upgrade kept the state: noneuclid scores, as the kiosk's user, has the game" kept_scores
    check "the upgrade kept the board override as the user edited it" ct grep -q -x 'idle_seconds = 300' /etc/noneuclid/board.toml
    check "the upgrade kept the unit enabled" [ "$(ct systemctl is-enabled noneuclid)" = enabled ]
    pid=$(main_pid)

    # -- remove
    ct apt-get -q -y -o Dpkg::Use-Pty=0 remove noneuclid >"$work/remove.log" 2>&1 || bad "apt-get remove noneuclid ($work/remove.log)"
    check "apt-get remove stopped the kiosk" gone "/proc/$pid"
    check "... and systemd has it stopped" stopped
    check "remove took the program and the unit" gone /usr/bin/noneuclid /usr/lib/systemd/system/noneuclid.service
    check "remove kept the user" user_exists
    check "remove kept the state and the board override" \
        ct sh -c 'test -s /var/lib/noneuclid/scores && grep -q -x "idle_seconds = 300" /etc/noneuclid/board.toml'

    # -- purge
    ct apt-get -q -y -o Dpkg::Use-Pty=0 purge noneuclid >"$work/purge.log" 2>&1 || bad "apt-get purge noneuclid ($work/purge.log)"
    check "purge removed the user and its group" no_user
    check "purge removed the state and /etc/noneuclid" gone /var/lib/noneuclid /etc/noneuclid
    check "purge removed the unit's enable link and its mask" no_links

    # -- what is left: the tree against the one before the install. The groups gpio and input,
    # made by the install when missing, stay (other programs use them): those lines are allowed,
    # and listed.
    d12_manifest "$root" >"$work/after.txt"
    local left unexplained
    left=$(diff "$work/before.txt" "$work/after.txt" | grep '^[<>]' || true)
    unexplained=$(grep -v -E '^> (group|gshadow): (gpio|input):' <<<"$left" || true)
    check "after purge the tree is as before the install, but for the groups gpio and input" [ -z "$unexplained" ]
    [ -z "$unexplained" ] || head -n 40 <<<"$unexplained" >&2
    [ -z "$left" ] || echo "  left on purpose: $(cut -c3- <<<"$left" | tr '\n' ' ')"
    d12_stop
    trap - EXIT
}
