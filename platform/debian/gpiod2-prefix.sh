#!/bin/sh
# A private libgpiod 2.x (v2 API) for building platform/linux/gpio_v2.cpp on Debian 12, whose
# own libgpiod-dev is 1.6 (v1 API). bookworm-backports has 2.1.3; installing it system-wide
# would replace the v1 -dev package, so this script never touches the system:
#
#   platform/debian/gpiod2-prefix.sh [DIR]      # default DIR: build/gpiod2
#   ARCH=arm64 platform/debian/gpiod2-prefix.sh  # another architecture: build/gpiod2-arm64
#
#  1. a private apt configuration (its own sources list, lists and cache under DIR/apt) runs
#     `apt-get update` and `apt-get download` for libgpiod-dev and libgpiod3 from
#     bookworm-backports, as root or as a plain user;
#  2. `dpkg -x` unpacks both into DIR/root, and libgpiod.pc's prefix is pointed there.
#
# The prefix is cached: a second run with DIR/root complete does nothing. Then configure with
#
#   cmake --preset static-gpiod2         # or: -DNONEUCLID_GPIOD_PREFIX=$PWD/build/gpiod2/root/usr
#
# and the build compiles gpio_v2.cpp and links DIR/root/usr/lib/<triple>/libgpiod.a.
# Needs: apt-get, dpkg (any Debian); network access to deb.debian.org (MIRROR= to change it).
set -eu

here=$(cd "$(dirname "$0")/../.." && pwd)
arch=${ARCH:-$(dpkg --print-architecture)}
if [ "$arch" = "$(dpkg --print-architecture)" ]; then
    dir=${1:-$here/build/gpiod2}
else
    dir=${1:-$here/build/gpiod2-$arch}
fi
mirror=${MIRROR:-http://deb.debian.org/debian}
suite=${SUITE:-bookworm-backports}
triple=$(dpkg-architecture -a"$arch" -qDEB_HOST_MULTIARCH 2>/dev/null) || case $arch in
    amd64) triple=x86_64-linux-gnu ;;
    arm64) triple=aarch64-linux-gnu ;;
    armhf) triple=arm-linux-gnueabihf ;;
    *) echo "gpiod2-prefix.sh: unknown architecture $arch: install dpkg-dev" >&2; exit 1 ;;
esac

root=$dir/root
stamp=$root/.complete-$arch
if [ -f "$stamp" ] && [ -f "$root/usr/include/gpiod.h" ] && [ -f "$root/usr/lib/$triple/libgpiod.a" ]; then
    echo "gpiod2-prefix.sh: cached in $root ($(cat "$stamp"))" >&2
    exit 0
fi

apt_dir=$dir/apt
mkdir -p "$apt_dir/empty" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/debs-$arch"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
signed=""
[ -f "$keyring" ] && signed=" signed-by=$keyring"
echo "deb [arch=$arch$signed] $mirror $suite main" >"$apt_dir/sources.list"

# Private state: nothing under /etc/apt, /var/lib/apt or /var/cache/apt is read for packages or
# written. As root, apt would hand downloads to the _apt user, who cannot write a private
# directory under a user's tree: download as the current user instead.
user=$(id -un)
apt_private() {
    apt-get -q \
        -o Dir::Etc::SourceList="$apt_dir/sources.list" \
        -o Dir::Etc::SourceParts=- \
        -o Dir::Etc::Preferences=/dev/null \
        -o Dir::Etc::PreferencesParts="$apt_dir/empty" \
        -o Dir::State::Lists="$apt_dir/lists" \
        -o Dir::Cache="$apt_dir/cache" \
        -o Dir::Cache::pkgcache="$apt_dir/cache/pkgcache.bin" \
        -o Dir::Cache::srcpkgcache="$apt_dir/cache/srcpkgcache.bin" \
        -o Debug::NoLocking=1 \
        -o APT::Sandbox::User="$user" \
        -o APT::Architecture="$arch" \
        -o APT::Architectures="$arch" \
        "$@"
}

# As in deps.sh: an index that fails to update (a mirror mid-sync) is not fatal by itself; the
# update is tried twice and the download decides. A failed download gets fresh lists and one
# more try, then the script stops, naming what it could not fetch.
update() {
    apt_private update </dev/null >&2 && return 0
    echo "gpiod2-prefix.sh: apt-get update reported errors (above); trying it once more in ${NONEUCLID_APT_RETRY_DELAY:-10} s" >&2
    sleep "${NONEUCLID_APT_RETRY_DELAY:-10}"
    apt_private update </dev/null >&2 ||
        echo "gpiod2-prefix.sh: apt-get update reported errors again (above); downloading anyway" >&2
}
download() {
    (cd "$apt_dir/debs-$arch" && rm -f ./*.deb &&
        apt_private download "libgpiod-dev:$arch/$suite" "libgpiod3:$arch/$suite" </dev/null >&2)
}
echo "gpiod2-prefix.sh: fetching libgpiod-dev and libgpiod3 ($arch) from $suite" >&2
update
download || { echo "gpiod2-prefix.sh: the download failed (above); updating and trying once more" >&2; update; download; } || {
    echo "gpiod2-prefix.sh: could not download libgpiod-dev and libgpiod3 ($arch) from $mirror $suite (twice; output above)" >&2
    exit 1
}

rm -rf "$root"
mkdir -p "$root"
for deb in "$apt_dir/debs-$arch"/*.deb; do
    dpkg -x "$deb" "$root"
done
pc=$root/usr/lib/$triple/pkgconfig/libgpiod.pc
if [ ! -f "$pc" ] || [ ! -f "$root/usr/lib/$triple/libgpiod.a" ]; then
    echo "gpiod2-prefix.sh: the downloaded packages lack $pc or libgpiod.a: has $suite changed?" >&2
    exit 1
fi
# Make the .pc relocatable to where it was unpacked, so PKG_CONFIG_PATH alone works too.
sed -i "s|^prefix=.*|prefix=$root/usr|" "$pc"
version=$(sed -n 's/^Version: *//p' "$pc")
echo "libgpiod $version" >"$stamp"
echo "gpiod2-prefix.sh: libgpiod $version in $root/usr" >&2
