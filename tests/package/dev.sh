# shellcheck shell=bash
# shellcheck disable=SC2154  # $work, $version, $host_build, $top, dev and triple are package-test's
# The library's package, noneuclid-dev (step 5 of tests/package/package-test, sourced from it;
# uses its ok, bad, check and variables): what each holds, and the amd64 one used as a project
# outside the tree uses it.

dev_package() {
    local arch x lib missing f
    for arch in amd64 arm64 armhf; do
        x=$work/x/$arch-dev
        dpkg-deb -x "${dev[$arch]}" "$x"
        lib=usr/lib/${triple[$arch]}
        missing=""
        for f in usr/include/noneuclid.h usr/include/noneuclid/world/world.hpp usr/include/noneuclid/render/canvas.hpp \
            "$lib"/libnoneuclid_fixed.a "$lib"/libnoneuclid_world.a "$lib"/libnoneuclid_render.a "$lib"/libnoneuclid_capi.a \
            "$lib"/cmake/noneuclid/noneuclidConfig.cmake "$lib"/cmake/noneuclid/noneuclidConfigVersion.cmake \
            "$lib"/cmake/noneuclid/noneuclidTargets.cmake usr/share/doc/noneuclid-dev/copyright; do
            [ -f "$x/$f" ] || missing="$missing $f"
        done
        # libnoneuclid.so natively only (NONEUCLID_CAPI_SHARED: not in the cross builds).
        [ "$arch" != amd64 ] || [ -f "$x/$lib/noneuclid/libnoneuclid.so" ] || missing="$missing $lib/noneuclid/libnoneuclid.so"
        check "$arch: noneuclid-dev holds the headers, the static libraries and the CMake package${missing:+ (missing:$missing)}" \
            [ -z "$missing" ]
        check "$arch: noneuclid-dev depends on libglm-dev (the headers include GLM's)" \
            bash -c "dpkg-deb -f '${dev[$arch]}' Depends | grep -q -w libglm-dev"
        check "$arch: noneuclid holds no header and no library of noneuclid-dev" \
            bash -c "! dpkg-deb -c '${deb[$arch]}' | grep -q -E 'usr/include|\\.a\$|libnoneuclid\\.so|cmake/noneuclid'"
    done

    # examples/ as a project of its own against the amd64 package alone (CMAKE_PREFIX_PATH: its
    # unpacked /usr), example_c (C, libnoneuclid.so) and example_picture (C++, the static
    # libraries) built and run; the packaged program renders the same pictures.
    x=$work/x/amd64-dev
    local tree=$work/dev-examples bin=$work/x/amd64/usr/bin/noneuclid
    rm -rf "$tree"
    if ! cmake -S "$top/examples" -B "$tree" -DCMAKE_PREFIX_PATH="$x/usr" -DCMAKE_BUILD_TYPE=Release >"$work/dev.log" 2>&1 ||
        ! cmake --build "$tree" --target example_c example_picture -j "$(nproc)" >>"$work/dev.log" 2>&1; then
        tail -n 30 "$work/dev.log" >&2
        bad "examples/ builds against the amd64 noneuclid-dev alone (the end of $work/dev.log above)"
        return
    fi
    ok "examples/ builds against the amd64 noneuclid-dev alone (find_package from its unpacked /usr)"
    "$tree/example_c" kiosk 30 240x160 rgb565 "$work/dev-c.ppm" >/dev/null || bad "example_c runs"
    "$bin" render --scene kiosk --frames 30 --size 240x160 --format rgb565 --out "$work/dev-c.png" >/dev/null 2>&1
    check "example_c built against noneuclid-dev draws noneuclid render's picture, pixel for pixel" \
        "$host_build/png_diff" "$work/dev-c.ppm" "$work/dev-c.png" --exact
    "$tree/example_picture" kiosk 30 240x160 "$work/dev-picture.ppm" || bad "example_picture runs"
    "$bin" render --scene kiosk --frames 30 --size 240x160 --out "$work/dev-picture.png" >/dev/null 2>&1
    check "example_picture built against noneuclid-dev draws noneuclid render's picture, pixel for pixel" \
        "$host_build/png_diff" "$work/dev-picture.ppm" "$work/dev-picture.png" --exact
}
