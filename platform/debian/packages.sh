#!/bin/sh
# The Debian packages noneuclid's scripts install, in named groups: the one place they are listed.
#
#   platform/debian/packages.sh build test          # the packages of these groups, one a line
#   platform/debian/packages.sh --archs cross       # the foreign architectures they need
#   platform/debian/packages.sh --install build     # install those missing (platform/debian/deps.sh)
#   platform/debian/packages.sh --groups            # the group names
#
#   . platform/debian/deps.sh; . platform/debian/packages.sh    # or source both, then:
#   noneuclid_packages build test      # the same list
#   noneuclid_install build test       # enable the foreign architectures, install what is missing
#
# Each group is whole: it names everything its job needs, partly through the groups it builds on
# (an @name below), so a script names only the groups of the jobs it does. The list printed is
# their union, each package once, in the order the groups are named. A package:ARCH is multiarch:
# the group needs ARCH enabled as a foreign architecture (--archs, noneuclid_install).

# The table: the words of group $1 (packages, and @group for another group's), or 1 if unknown.
_np_group() {
    case $1 in
        # Configuring and compiling any preset: the compiler, CMake and the header-only libraries.
        core) echo g++ cmake make pkg-config libglm-dev libtomlplusplus-dev ;;
        # Building and running the program (the release preset), and its manual page (help2man,
        # small: the perl it needs comes with git and dpkg-dev).
        build) echo @core libpng-dev libgif-dev zlib1g-dev libx11-dev libxext-dev libgpiod-dev libasound2-dev help2man ;;
        # The native test suite: GoogleTest, Google Benchmark, the Cairo reference, a virtual X
        # server driven by xdotool and read with xwininfo (x11-utils); shellcheck for the scripts;
        # PROJ's proj (proj-bin) for the earth scene's check against its projections; ccache,
        # with which run-tests compiles once what its trees compile alike; python3, which runs the
        # library's examples' checks and its ctypes example (tests/library); poppler-utils, whose
        # pdfinfo and pdftoppm read the worksheets' PDFs back (tests/app/test_worksheet.cpp).
        test) echo @build libgtest-dev libbenchmark-dev libcairo2-dev xvfb xdotool x11-utils shellcheck proj-bin ccache python3 poppler-utils ;;
        # The libFuzzer harnesses (the fuzz preset): clang 14 and libFuzzer's runtime.
        fuzz) echo @build clang-14 libclang-rt-14-dev ;;
        # The Raspberry Pi's architectures: a cross compiler with the target's libc, qemu-user
        # to run the tests, GoogleTest's sources (the cross presets build their tests) and the
        # target's libgpiod.
        cross-arm64) echo @core crossbuild-essential-arm64 qemu-user libgtest-dev libgpiod-dev:arm64 ;;
        cross-armhf) echo @core crossbuild-essential-armhf qemu-user libgtest-dev libgpiod-dev:armhf ;;
        cross) echo @cross-arm64 @cross-armhf ;;
        # The microcontroller firmware (platform/mcu) and its test under emulation (tests/mcu):
        # the bare-metal ARM compiler, newlib and its C++ library, and qemu-system-arm for the
        # Cortex-M3 board (mps2-an385); the native build that renders the reference is test's.
        mcu) echo @core gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm ;;
        # The web page (the web preset): no host compiler, emscripten brings clang, lld,
        # binaryen, Node.js and Python.
        web) echo cmake make libglm-dev libtomlplusplus-dev emscripten ;;
        # The page's test (tests/web/run): it runs in headless Chromium.
        web-test) echo @web chromium ;;
        # The system test (tests/system/run): qemu, the initramfs's busybox, cpio and kmod
        # (depmod, modprobe), and gpio-sim.ko built from linux-source against the headers of the
        # kernel that linux-image-amd64 depends on (the kernel itself is downloaded, not installed).
        system) _np_abi=$(noneuclid_kernel_abi)
                if [ -z "$_np_abi" ]; then
                    [ -n "${_np_quiet:-}" ] ||
                        echo "packages.sh: cannot tell which kernel linux-image-amd64 depends on (apt-cache depends linux-image-amd64): no package lists yet? (apt-get update)" >&2
                    return 1
                fi
                echo qemu-system-x86 busybox-static cpio kmod gcc libc6-dev make \
                    "linux-headers-$_np_abi-amd64" linux-source-6.1 ;;
        # Making the Debian packages (platform/debian/build-packages, CPack): the manual page, and
        # dpkg-shlibdeps (dpkg-dev) and file for the Depends field. Each architecture's build is
        # build's or cross-<arch>'s.
        package) echo @core help2man dpkg-dev file ;;
        # Testing them (tests/package/package-test): lintian, a Debian 12 tree booted with
        # systemd-nspawn, readelf (binutils), pgrep (procps), the ARM binaries under qemu-user;
        # the compiler and CMake (core) for an example built against noneuclid-dev.
        package-test) echo @core lintian debootstrap systemd-container dpkg-dev binutils procps qemu-user ;;
        *) return 1 ;;
    esac
}
_np_names="core build test fuzz cross-arm64 cross-armhf cross mcu web web-test system package package-test"

# The kernel ABI Debian's linux-image-amd64 points at, e.g. 6.1.0-56 (empty without package lists).
noneuclid_kernel_abi() {
    { apt-cache depends linux-image-amd64 2>/dev/null || true; } |
        awk 'sub(/^ *Depends: linux-image-/, "") && sub(/-amd64$/, "") { print; exit }'
}

# The words of the groups, @groups expanded, with repeats; 2 for an unknown group, 1 if a group
# cannot be listed.
_np_expand() {
    for _np_g in "$@"; do
        _np_words=$(_np_group "$_np_g") || {
            # An unknown name (not a failure of a known group's own, which has said why).
            case " $_np_names " in
                *" $_np_g "*) return 1 ;;
                *) echo "packages.sh: no group '$_np_g' (the groups: $_np_names)" >&2; return 2 ;;
            esac
        }
        for _np_w in $_np_words; do
            case $_np_w in
                @*) (_np_expand "${_np_w#@}") || return ;;
                *) echo "$_np_w" ;;
            esac
        done
    done
}

# noneuclid_packages GROUP...: the union of the groups' packages, one a line, each once.
noneuclid_packages() {
    [ $# -gt 0 ] || { echo "packages.sh: name at least one group ($_np_names)" >&2; return 2; }
    _np_all=$(_np_expand "$@") || return
    printf '%s\n' "$_np_all" | awk '!seen[$0]++'
}

# _np_archs PACKAGE...: the foreign architectures of the multiarch ones, one a line, each once.
_np_archs() {
    for _np_p in "$@"; do
        case $_np_p in
            *:*) echo "${_np_p##*:}" ;;
        esac
    done | awk '!seen[$0]++'
}

# noneuclid_install GROUP...: enables the foreign architectures the groups need and installs
# their packages that are missing, with platform/debian/deps.sh's functions (source it first).
noneuclid_install() {
    command -v noneuclid_deps >/dev/null 2>&1 || {
        echo "packages.sh: noneuclid_install needs platform/debian/deps.sh sourced first" >&2
        return 2
    }
    _np_list=$(_np_quiet=1 noneuclid_packages "$@") || {
        # An unknown group has been named (2). A group that needs the package lists (system:
        # the kernel's ABI) gets them, as on a fresh machine, and is listed once more (an index
        # that fails to update is reported, not fatal: deps.sh).
        _np_rc=$?
        [ "$_np_rc" -eq 1 ] || return "$_np_rc"
        noneuclid_apt_update >&2
        _np_list=$(noneuclid_packages "$@") || return
    }
    # shellcheck disable=SC2086  # the list is one package a word
    _np_foreign=$(_np_archs $_np_list)
    if [ -n "$_np_foreign" ]; then
        # shellcheck disable=SC2086  # one architecture a word
        noneuclid_foreign_archs $_np_foreign || return
    fi
    # shellcheck disable=SC2086  # one package a word
    noneuclid_deps $_np_list
}

# Run as a program (not sourced).
case ${0##*/} in
    packages.sh)
        case ${1:-} in
            --groups) echo "$_np_names" | tr ' ' '\n'; exit 0 ;;
            --archs) shift; _np_list=$(noneuclid_packages "$@") || exit
                     # shellcheck disable=SC2086  # one package a word
                     _np_archs $_np_list; exit 0 ;;
            --install) shift
                       # shellcheck source=platform/debian/deps.sh
                       . "$(dirname "$0")/deps.sh"
                       noneuclid_install "$@"; exit ;;
            -*) echo "packages.sh: unknown option '$1' (--groups, --archs, --install, or group names)" >&2; exit 2 ;;
        esac
        noneuclid_packages "$@"; exit ;;
esac
